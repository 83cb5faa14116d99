#include "analysis/audit/gap_target.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace ms::audit {

GapTarget::GapTarget(const AuditData& data, const std::vector<std::size_t>& strikes)
    : strikes_(strikes), measured_db_(strikes.size()), floor_db_(strikes.size()), floor_power_(strikes.size()) {
  for (std::size_t i = 0; i < strikes.size(); ++i)
    for (std::size_t r = 0; r < kResolutions; ++r) {
      const BarkSpectrogram& m = data.measured.strikes[strikes[i]].spectra[r];
      double peak = -400.0;
      for (double p : m.power) peak = std::max(peak, level_db(p));
      floor_db_[i][r] = peak - kGapFloorDb;
      floor_power_[i][r] = std::pow(10.0, floor_db_[i][r] / 10.0);
      for (double p : m.power) measured_db_[i][r].push_back(std::max(level_db(p), floor_db_[i][r]));
    }
}

double quick_level_db(double p) {
  // p = m 2^e, m in [1, 2), ln m = 2 (s + s^3/3 + ... + s^11/11) with s = (m - 1) / (m + 1) <= 1/3.
  if (!(p > 0.0) || !std::isfinite(p)) return level_db(p);
  std::uint64_t bits;
  std::memcpy(&bits, &p, sizeof bits);
  const int exponent = int((bits >> 52) & 0x7ff) - 1023;
  if (exponent == -1023) return level_db(p);  // subnormal
  bits = (bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
  double m;
  std::memcpy(&m, &bits, sizeof m);
  const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
  const double ln_m = 2.0 * s * (1.0 + s2 * (1.0 / 3 + s2 * (1.0 / 5 + s2 * (1.0 / 7 + s2 * (1.0 / 9 + s2 / 11)))));
  constexpr double kDbPerLn = 4.342944819032518, kDbPerOctave = 3.0102999566398120;
  return kDbPerLn * ln_m + kDbPerOctave * double(exponent);
}

double GapTarget::strike_gap(std::size_t i, const Spectra& model) const {
  double total = 0.0;
  std::size_t count = 0;
  for (std::size_t r = 0; r < kResolutions; ++r) {
    const std::vector<double>& meas = measured_db_[i][r];
    const double floor = floor_db_[i][r], floor_power = floor_power_[i][r];
    const std::vector<double>& power = model[r].power;
    for (std::size_t c = 0; c < meas.size() && c < power.size(); ++c) {
      // Under the floor a level needs no logarithm.
      const double a = meas[c], b = power[c] > floor_power ? quick_level_db(power[c]) : floor;
      if (a <= floor && b <= floor) continue;
      total += std::abs(b - a);
      ++count;
    }
  }
  return count > 0 ? total / double(count) : 0.0;
}

}  // namespace ms::audit
