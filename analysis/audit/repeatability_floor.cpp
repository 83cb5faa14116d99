#include "analysis/audit/repeatability_floor.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "analysis/audit/parallel_indices.hpp"

namespace ms::audit {

namespace {

// Residuals are read this far below a measured spectrogram's loudest cell (deeper than the gap's floor,
// so cells near it keep their level).
constexpr double kResidualRangeDb = kGapFloorDb + 20.0;

double peak_db(const BarkSpectrogram& s) {
  double p = -400.0;
  for (double v : s.power) p = std::max(p, level_db(v));
  return p;
}

}  // namespace

RepeatabilityFloor repeatability_floor(const AuditData& data, const Recipe& recipe) {
  std::vector<AuditModel> folds;
  cross_validated_gap(data, recipe, &folds);
  return repeatability_floor(data, folds);
}

RepeatabilityFloor repeatability_floor(const AuditData& data, const std::vector<AuditModel>& fold_models) {
  RepeatabilityFloor out;
  const std::size_t n = data.strike_count();
  if (n < 2 || fold_models.size() != n) return out;
  // Each held-out strike's floor stands alone: they are read side by side, each into its own slot.
  out.strike_gap_db.assign(n, 0.0);
  out.strike_best_db.assign(n, 0.0);
  out.strike_floor_db.assign(n, 0.0);
  parallel_indices(n, [&](std::size_t k) {
    std::vector<std::size_t> train;
    for (std::size_t s = 0; s < n; ++s)
      if (s != k) train.push_back(s);
    const AuditModel& model = fold_models[k];
    Spectra best = predict_spectra(model, data, k);
    const double plain_gap_db = gap_map(data.measured.strikes[k].spectra, best).gap_db;
    out.strike_gap_db[k] = plain_gap_db;
    // dB residual of the training strikes per cell, each clamped below its own measured peak: its mean,
    // shrunk towards 0 by the positive-part James-Stein factor 1 - (standard error / mean)^2, so that
    // residuals the strikes do not agree on (each strike's own scatter) stay out of the best model.
    std::array<std::vector<double>, kResolutions> sum_db, sum_sq_db;
    for (std::size_t r = 0; r < kResolutions; ++r) {
      sum_db[r].assign(best[r].power.size(), 0.0);
      sum_sq_db[r].assign(best[r].power.size(), 0.0);
    }
    for (std::size_t j : train) {
      const Spectra predicted = predict_spectra(model, data, j);
      const Spectra& measured = data.measured.strikes[j].spectra;
      for (std::size_t r = 0; r < kResolutions; ++r) {
        const double floor = peak_db(measured[r]) - kResidualRangeDb;
        for (std::size_t i = 0; i < sum_db[r].size() && i < measured[r].power.size(); ++i) {
          const double d = std::max(level_db(measured[r].power[i]), floor) - std::max(level_db(predicted[r].power[i]), floor);
          sum_db[r][i] += d;
          sum_sq_db[r][i] += d * d;
        }
      }
    }
    const double m = double(train.size());
    const Spectra& held_out = data.measured.strikes[k].spectra;
    for (std::size_t r = 0; r < kResolutions; ++r) {
      const double floor = peak_db(held_out[r]) - kResidualRangeDb;
      for (std::size_t i = 0; i < best[r].power.size(); ++i) {
        const double mean = sum_db[r][i] / m;
        const double variance_of_mean = m > 1.0 ? std::max(0.0, sum_sq_db[r][i] / m - mean * mean) / (m - 1.0) : 0.0;
        const double shrink = mean != 0.0 ? std::max(0.0, 1.0 - variance_of_mean / (mean * mean)) : 0.0;
        const double level = std::max(level_db(best[r].power[i]), floor) + shrink * mean;
        best[r].power[i] = std::pow(10.0, level / 10.0);
      }
    }
    // Residuals that follow a per-strike value (a contact's notches move with the strike) do not carry
    // over to strike k; then the fold's own model is the better model of the others.
    out.strike_best_db[k] = gap_map(held_out, best).gap_db;
    out.strike_floor_db[k] = std::min(out.strike_best_db[k], plain_gap_db);
  });
  double sum = 0.0;
  for (double g : out.strike_floor_db) sum += g;
  out.floor_db = sum / double(n);
  return out;
}

SharedResidual shared_residual(const RepeatabilityFloor& floor) {
  const std::size_t n = std::min(floor.strike_gap_db.size(), floor.strike_best_db.size());
  SharedResidual out;
  if (n == 0) return out;
  double sum = 0.0, sum_sq = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double d = floor.strike_gap_db[k] - floor.strike_best_db[k];
    sum += d;
    sum_sq += d * d;
  }
  out.mean_db = sum / double(n);
  if (n > 1) out.standard_error_db = std::sqrt(std::max(0.0, sum_sq / double(n) - out.mean_db * out.mean_db) / double(n - 1));
  return out;
}

double share_above_floor(double improvement_db, double gap_db, double floor_db) {
  const double above = gap_db - floor_db;
  return above > 0.0 ? improvement_db / above : 0.0;
}

}  // namespace ms::audit
