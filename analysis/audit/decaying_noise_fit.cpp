#include "analysis/audit/decaying_noise_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "analysis/audit/gap_target.hpp"
#include "analysis/audit/grid_cross_validation.hpp"

namespace ms::audit {

DecayingNoiseFit fit_decaying_noise(const AuditData& data, const AuditModel& without,
                                    const std::vector<std::size_t>& strikes, double t60_min_s, double t60_max_s,
                                    double level_min_db, double level_max_db, bool refine,
                                    const std::vector<NoiseBand>& bands, const std::vector<double>& holds_s) {
  // The modal rendering does not depend on the noise: render once per strike, add the noise analytically.
  std::vector<Spectra> base;
  std::vector<double> energy;
  for (std::size_t s : strikes) {
    double e = 0.0;
    base.push_back(predict_spectra(without, data, s, &e));
    energy.push_back(e);
  }
  const GapTarget target(data, strikes);
  // A burst changes a strike's first frames only: the gap re-reads those, and the rest is summed once.
  std::vector<GapTarget::FrameTails> tails;
  for (std::size_t i = 0; i < strikes.size(); ++i) tails.push_back(target.frame_tails(i, base[i]));
  std::vector<Spectra> work = base;  // base[i] but for the frames the noise being tried changed
  const Grids& grids = data.measured.grids;
  std::vector<double> per_strike(strikes.size());
  NoiseBand band;
  double hold_s = 0.0;
  std::array<std::vector<double>, kResolutions> band_bins;  // burst_bins_per_band of `band` per grid
  const auto gap_of = [&](double t60, double level) {
    double sum = 0.0;
    for (std::size_t i = 0; i < strikes.size(); ++i) {
      std::array<std::size_t, kResolutions> changed{};
      for (std::size_t r = 0; r < kResolutions; ++r)
        changed[r] = add_decaying_noise_power(work[i][r], grids[r], energy[i], t60, level,
                                              band.high_hz > 0.0 ? &band_bins[r] : nullptr, hold_s);
      per_strike[i] = target.strike_gap(i, work[i], changed, tails[i]);
      sum += per_strike[i];
      for (std::size_t r = 0; r < kResolutions; ++r) {
        const std::size_t cells = changed[r] * base[i][r].bands;
        std::copy_n(base[i][r].power.begin(), cells, work[i][r].power.begin());
      }
    }
    return strikes.empty() ? 0.0 : sum / double(strikes.size());
  };
  const auto use_band = [&](const NoiseBand& b) {
    band = b;
    if (band.high_hz > 0.0)
      for (std::size_t r = 0; r < kResolutions; ++r) band_bins[r] = burst_bins_per_band(grids[r], band.low_hz, band.high_hz);
  };
  use_band(bands.empty() ? NoiseBand{} : bands.front());
  DecayingNoiseFit best;
  best.t60_s = t60_min_s;
  best.level_db = level_min_db;
  best.band = band;
  best.gap_db = gap_of(best.t60_s, best.level_db);
  std::vector<std::vector<double>> table;  // the coarse grid's per-strike gaps
  const auto search = [&](double lt_lo, double lt_hi, int nt, double l_lo, double l_hi, int nl, bool tabulate) {
    for (int i = 0; i < nt; ++i) {
      const double t60 = std::exp(lt_lo + (lt_hi - lt_lo) * double(i) / double(std::max(nt - 1, 1)));
      for (int j = 0; j < nl; ++j) {
        const double level = l_lo + (l_hi - l_lo) * double(j) / double(std::max(nl - 1, 1));
        const double gap = gap_of(t60, level);
        if (tabulate) table.push_back(per_strike);
        if (gap < best.gap_db) {
          best.t60_s = t60;
          best.level_db = level;
          best.band = band;
          best.hold_s = hold_s;
          best.gap_db = gap;
        }
      }
    }
  };
  const double lt_min = std::log(t60_min_s), lt_max = std::log(t60_max_s);
  const double coarse_t = (lt_max - lt_min) / 5.0, coarse_l = (level_max_db - level_min_db) / 7.0;
  for (const NoiseBand& b : bands.empty() ? std::vector<NoiseBand>{NoiseBand{}} : bands) {
    use_band(b);
    search(lt_min, lt_max, 6, level_min_db, level_max_db, 8, bands.size() <= 1);
  }
  use_band(best.band);
  for (double h : holds_s) {
    if (h <= 0.0) continue;
    hold_s = h;
    search(lt_min, lt_max, 6, level_min_db, level_max_db, 8, false);
  }
  if (bands.size() <= 1 && holds_s.size() <= 1) best.grid_cv_gap_db = leave_one_out_gap(table);
  if (!refine) return best;
  hold_s = best.hold_s;
  // Refine twice around the best cell (5 x 5, a quarter of the step each time), inside the ranges.
  for (double k : {0.5, 0.125}) {
    const double lt = std::log(best.t60_s);
    search(std::max(lt_min, lt - 2 * k * coarse_t), std::min(lt_max, lt + 2 * k * coarse_t), 5,
           std::max(level_min_db, best.level_db - 2 * k * coarse_l), std::min(level_max_db, best.level_db + 2 * k * coarse_l), 5,
           false);
  }
  return best;
}

}  // namespace ms::audit
