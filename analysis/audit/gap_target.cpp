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
