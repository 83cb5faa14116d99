// The repeatability floor: the gap that remains between a held-out strike and the best model the
// other strikes allow. Fold k fits the recipe on the other strikes and gives strike k its latent values
// (gain, and each named effect's per-strike values); the best model of strike k is then that model's
// prediction for k corrected, cell by cell of both spectrograms, by the mean dB residual
// (measured - model) of the training strikes: whatever the other strikes agree on beyond the model is
// predicted, so what is left is how much repeated strikes disagree (where the fold's plain model does
// better on strike k, residuals tied to a per-strike value, that gap is the floor). Gain-only copies of one recording
// give 0 dB; strikes that move (per-strike mode amplitudes beyond a gain) give a floor no catalog
// effect can close.
#pragma once
#include <vector>

#include "analysis/audit/audit_model.hpp"
#include "analysis/audit/cross_validation.hpp"

namespace ms::audit {

struct RepeatabilityFloor {
  double floor_db = 0.0;                // mean over the folds (dB, the gap metric)
  std::vector<double> strike_floor_db;  // per held-out strike
  std::vector<double> strike_gap_db;    // per held-out strike, the fold's own model (the held-out gap)
  std::vector<double> strike_best_db;   // per held-out strike, the best model of the others alone
};

// Leave-one-strike-out over every strike (needs at least 2).
RepeatabilityFloor repeatability_floor(const AuditData& data, const Recipe& recipe);

// The same from the fold models cross_validated_gap gave for a recipe (one per strike).
RepeatabilityFloor repeatability_floor(const AuditData& data, const std::vector<AuditModel>& fold_models);

// Share of the held-out gap above the floor that an improvement closes (0 when nothing lies above it).
double share_above_floor(double improvement_db, double gap_db, double floor_db);

// What the other strikes agree on beyond the model: per strike, the fold model's held-out gap minus the
// best model's (taken before the floor keeps the smaller of the two, so that it can be negative: where
// the strikes share nothing beyond the model, their mean residual only adds their scatter), its mean and
// standard error over the strikes. Resolved: more than two standard errors, and more than what the plain
// model's own imperfection leaves strikes to share on clean objects (kSharedResolutionDb); otherwise
// nothing the strikes share is missing (an effect that varies from strike to strike, such as a moving hit
// point, counts as repetition here as in the floor: its own detector must find it).
// Clean tuning cases: the first generator's with 1-3 dB of jitter 0.000-0.019 dB, the independent
// generator's (40600-40709) 0.00-0.02 dB; its cases hiding an effect where nothing was named 0.01-0.11.
constexpr double kSharedResolutionDb = 0.05;
struct SharedResidual {
  double mean_db = 0.0, standard_error_db = 0.0;
  bool resolved() const { return mean_db > 2.0 * standard_error_db && mean_db > kSharedResolutionDb; }
};
SharedResidual shared_residual(const RepeatabilityFloor& floor);

}  // namespace ms::audit
