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

void GapTarget::accumulate(std::size_t i, std::size_t r, const std::vector<double>& power, std::size_t from,
                           std::size_t to, double& total, std::size_t& count) const {
  const std::vector<double>& meas = measured_db_[i][r];
  const double floor = floor_db_[i][r], floor_power = floor_power_[i][r];
  to = std::min({to, meas.size(), power.size()});
  for (std::size_t c = from; c < to; ++c) {
    // Under the floor a level needs no logarithm.
    const double a = meas[c], b = power[c] > floor_power ? quick_level_db(power[c]) : floor;
    if (a <= floor && b <= floor) continue;
    total += std::abs(b - a);
    ++count;
  }
}

double GapTarget::strike_gap(std::size_t i, const Spectra& model) const {
  double total = 0.0;
  std::size_t count = 0;
  for (std::size_t r = 0; r < kResolutions; ++r) accumulate(i, r, model[r].power, 0, model[r].power.size(), total, count);
  return count > 0 ? total / double(count) : 0.0;
}

GapTarget::FrameTails GapTarget::frame_tails(std::size_t i, const Spectra& base) const {
  FrameTails tails;
  for (std::size_t r = 0; r < kResolutions; ++r) {
    const BarkSpectrogram& b = base[r];
    tails.total[r].assign(b.frames + 1, 0.0);
    tails.count[r].assign(b.frames + 1, 0);
    for (std::size_t f = b.frames; f-- > 0;) {
      double total = 0.0;
      std::size_t count = 0;
      accumulate(i, r, b.power, f * b.bands, (f + 1) * b.bands, total, count);
      tails.total[r][f] = tails.total[r][f + 1] + total;
      tails.count[r][f] = tails.count[r][f + 1] + count;
    }
  }
  return tails;
}

double GapTarget::strike_gap(std::size_t i, const Spectra& model, const std::array<std::size_t, kResolutions>& changed_frames,
                             const FrameTails& tails) const {
  double total = 0.0;
  std::size_t count = 0;
  for (std::size_t r = 0; r < kResolutions; ++r) {
    const std::size_t f = std::min(changed_frames[r], tails.total[r].size() - 1);
    accumulate(i, r, model[r].power, 0, f * model[r].bands, total, count);
    total += tails.total[r][f];
    count += tails.count[r][f];
  }
  return count > 0 ? total / double(count) : 0.0;
}

}  // namespace ms::audit
