// Fitting a model recipe (baseline + named effects) on some strikes and scoring it on held-out ones:
// leave-one-strike-out, the held-out strike contributing only its latent values (gain, and the
// per-strike values an effect declares), so an effect must predict the rest to lower the gap.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "analysis/audit/audit_model.hpp"
#include "analysis/audit/effect_catalog.hpp"

namespace ms::audit {

struct Recipe {
  std::optional<AuditModel> given;        // a parameter set's baseline (else: fitted from the recordings)
  std::vector<const Effect*> effects;     // in the order named
};

// Baseline fitted on `train`, each effect extended on `train` in order, latent values of the train strikes.
AuditModel fit_recipe(const AuditData& data, const Recipe& recipe, const std::vector<std::size_t>& train);

// The latent values of strike s (gain, then each effect's, then the gain again).
void adapt_strike(const AuditData& data, const Recipe& recipe, AuditModel& model, std::size_t strike);

// Fold k's model fitted on every strike but k, before strike k's latent values, for a recipe's
// effects. Fitting is deterministic, so a recipe that adds effects to these starts its folds from them
// and extends only the new ones: the audit's later rounds then do not refit the baseline and every
// effect named before (a room's fit among them) once per candidate and fold.
struct TrainedFolds {
  std::vector<const Effect*> effects;
  std::vector<AuditModel> models;  // one per strike held out
};

// Mean held-out gap (dB) over leave-one-strike-out folds; with a single strike the in-sample gap.
// fold_models (if given) receives fold k's model (fitted without strike k, then given its latent values)
// for every k; strike_gaps_db (if given) strike k's held-out gap. from (if given, for the same
// recipe.given, its effects the first of recipe.effects): the folds start from its models. trained (if
// given) receives this recipe's.
double cross_validated_gap(const AuditData& data, const Recipe& recipe, std::vector<AuditModel>* fold_models = nullptr,
                           std::vector<double>* strike_gaps_db = nullptr, const TrainedFolds* from = nullptr,
                           TrainedFolds* trained = nullptr);

// In-sample: fitted on every strike, mean gap over every strike.
double in_sample_gap(const AuditData& data, const Recipe& recipe, AuditModel* fitted = nullptr);

// fit_recipe on every strike, from the model of every effect but the last (`before`, as fit_recipe made
// it) and, where the last effect's detector built it, `before` with that effect extended on every strike:
// fitting is deterministic, so this is the same model without fitting the baseline and the effects
// before it again.
AuditModel fit_last_effect(const AuditData& data, const Recipe& recipe, const AuditModel& before,
                           const std::optional<AuditModel>& extended);

}  // namespace ms::audit
