#include "analysis/audit/decaying_noise_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ms::audit {

DecayingNoiseFit fit_decaying_noise(const AuditData& data, const AuditModel& without,
                                    const std::vector<std::size_t>& strikes, double t60_min_s, double t60_max_s,
                                    double level_min_db, double level_max_db) {
  // The modal rendering does not depend on the noise: render once per strike, add the noise analytically.
  std::vector<Spectra> base;
  std::vector<double> energy;
  for (std::size_t s : strikes) {
    double e = 0.0;
    base.push_back(predict_spectra(without, data, s, &e));
    energy.push_back(e);
  }
  // gap_map's arithmetic with the measured levels clamped once (the search evaluates ~100 candidates).
  const Grids& grids = data.measured.grids;
  std::vector<std::array<std::vector<double>, kResolutions>> measured_db(strikes.size());
  std::vector<std::array<double, kResolutions>> floor_db(strikes.size());
  for (std::size_t i = 0; i < strikes.size(); ++i)
    for (std::size_t r = 0; r < kResolutions; ++r) {
      const BarkSpectrogram& m = data.measured.strikes[strikes[i]].spectra[r];
      double peak = -400.0;
      for (double p : m.power) peak = std::max(peak, level_db(p));
      floor_db[i][r] = peak - kGapFloorDb;
      for (double p : m.power) measured_db[i][r].push_back(std::max(level_db(p), floor_db[i][r]));
    }
  BarkSpectrogram spec;
  const auto gap_of = [&](double t60, double level) {
    double sum = 0.0;
    for (std::size_t i = 0; i < strikes.size(); ++i) {
      double total = 0.0;
      std::size_t count = 0;
      for (std::size_t r = 0; r < kResolutions; ++r) {
        spec = base[i][r];
        add_decaying_noise_power(spec, grids[r], energy[i], t60, level);
        const std::vector<double>& meas = measured_db[i][r];
        const double floor = floor_db[i][r];
        for (std::size_t c = 0; c < meas.size() && c < spec.power.size(); ++c) {
          const double a = meas[c], b = std::max(level_db(spec.power[c]), floor);
          if (a <= floor && b <= floor) continue;
          total += std::abs(b - a);
          ++count;
        }
      }
      sum += count > 0 ? total / double(count) : 0.0;
    }
    return strikes.empty() ? 0.0 : sum / double(strikes.size());
  };
  DecayingNoiseFit best;
  best.t60_s = t60_min_s;
  best.level_db = level_min_db;
  best.gap_db = gap_of(best.t60_s, best.level_db);
  const auto search = [&](double lt_lo, double lt_hi, int nt, double l_lo, double l_hi, int nl) {
    for (int i = 0; i < nt; ++i) {
      const double t60 = std::exp(lt_lo + (lt_hi - lt_lo) * double(i) / double(std::max(nt - 1, 1)));
      for (int j = 0; j < nl; ++j) {
        const double level = l_lo + (l_hi - l_lo) * double(j) / double(std::max(nl - 1, 1));
        const double gap = gap_of(t60, level);
        if (gap < best.gap_db) best = {t60, level, gap};
      }
    }
  };
  const double lt_min = std::log(t60_min_s), lt_max = std::log(t60_max_s);
  const double coarse_t = (lt_max - lt_min) / 5.0, coarse_l = (level_max_db - level_min_db) / 7.0;
  search(lt_min, lt_max, 6, level_min_db, level_max_db, 8);
  // Refine twice around the best cell (5 x 5, a quarter of the step each time), inside the ranges.
  for (double k : {0.5, 0.125}) {
    const double lt = std::log(best.t60_s);
    search(std::max(lt_min, lt - 2 * k * coarse_t), std::min(lt_max, lt + 2 * k * coarse_t), 5,
           std::max(level_min_db, best.level_db - 2 * k * coarse_l), std::min(level_max_db, best.level_db + 2 * k * coarse_l), 5);
  }
  return best;
}

}  // namespace ms::audit
