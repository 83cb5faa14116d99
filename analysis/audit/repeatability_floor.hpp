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
};

// Leave-one-strike-out over every strike (needs at least 2).
RepeatabilityFloor repeatability_floor(const AuditData& data, const Recipe& recipe);

// The same from the fold models cross_validated_gap gave for a recipe (one per strike).
RepeatabilityFloor repeatability_floor(const AuditData& data, const std::vector<AuditModel>& fold_models);

// Share of the held-out gap above the floor that an improvement closes (0 when nothing lies above it).
double share_above_floor(double improvement_db, double gap_db, double floor_db);

}  // namespace ms::audit
