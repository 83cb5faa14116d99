// noise_floor: stationary background noise the modal model does not produce. Detector: the
// measured band levels in the last 40 % of each strike stand above the model's by a stationary
// amount, and adding that noise power per Bark band lowers the gap by enough. Extension: one noise
// power per band, the median over the training strikes (a room's noise does not follow the strike).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/audit/effect_catalog.hpp"

namespace ms::audit {

namespace {

constexpr double kMinGapImprovementDb = 0.3;  // in-sample gap improvement (tuning seeds)
constexpr double kTailShare = 0.4;

void extend(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train) {
  const SpectrogramGrid& g = data.measured.grids[kDecay];
  std::vector<std::vector<double>> per_band(g.bands);
  AuditModel quiet = model;
  quiet.noise_band_variance.clear();
  const std::size_t first = std::size_t(double(g.frames) * (1.0 - kTailShare));
  for (std::size_t s : train) {
    const BarkSpectrogram pred = predict_spectra(quiet, data, s)[kDecay];
    const BarkSpectrogram& meas = data.measured.strikes[s].spectra[kDecay];
    for (std::size_t b = 0; b < g.bands; ++b) {
      std::vector<double> excess;
      for (std::size_t f = first; f < g.frames; ++f) excess.push_back(std::max(0.0, meas.at(f, b) - pred.at(f, b)));
      per_band[b].push_back(median(excess));
    }
  }
  // Band power -> white-equivalent variance (the same noise seen at every resolution).
  model.noise_band_variance.assign(g.bands, 0.0);
  for (std::size_t b = 0; b < g.bands; ++b)
    if (g.band_bins[b] > 0) model.noise_band_variance[b] = median(per_band[b]) / (g.window_energy * double(g.band_bins[b]));
}

Detection detect(const AuditData& data, const AuditModel& current) {
  return detect_by_gap_improvement(data, current, extend, kMinGapImprovementDb,
                                   [](const AuditModel&, double before, double after) {
                                     char buf[300];
                                     std::snprintf(buf, sizeof buf,
                                                   "the decayed tails stay at a stationary floor the model lacks; "
                                                   "adding it per Bark band lowers the gap from %.2f to %.2f dB",
                                                   before, after);
                                     return std::string(buf);
                                   });
}

// White-noise standard deviation with the same total power (full scale 1).
double white_sigma(const AuditData& data, const AuditModel& model) {
  const SpectrogramGrid& g = data.measured.grids[kDecay];
  double variance = 0.0, bins = 0.0;
  for (std::size_t b = 0; b < g.bands && b < model.noise_band_variance.size(); ++b) {
    variance += model.noise_band_variance[b] * double(g.band_bins[b]);
    bins += double(g.band_bins[b]);
  }
  return bins > 0 ? std::sqrt(variance / bins) : 0.0;
}

Parameters parameters(const AuditData& data, const AuditModel& model) {
  const double sigma = white_sigma(data, model);
  return {{"noise_sigma", sigma}, {"noise_floor_db", sigma > 0 ? 20.0 * std::log10(sigma) : -400.0}};
}

}  // namespace

double noise_white_sigma(const AuditData& data, const AuditModel& model) { return white_sigma(data, model); }

Effect noise_floor_effect() {
  return {.name = "noise_floor", .min_strikes = 1, .penalty_db = 0.05,
          .detect = detect, .extend = extend, .parameters = parameters};
}

}  // namespace ms::audit
