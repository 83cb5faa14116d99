#include "analysis/audit/cross_validation.hpp"

#include <algorithm>

#include "analysis/audit/baseline_fit.hpp"
#include "analysis/audit/parallel_indices.hpp"

namespace ms::audit {

void adapt_strike(const AuditData& data, const Recipe& recipe, AuditModel& model, std::size_t s) {
  fit_gain(model, data, s);
  for (const Effect* e : recipe.effects)
    if (e->adapt) e->adapt(data, model, s);
  fit_gain(model, data, s);
}

namespace {

// Effects first.. of the recipe extended on `train` in order, the train strikes' latent values after each.
void extend_recipe(const AuditData& data, const Recipe& recipe, AuditModel& model, const std::vector<std::size_t>& train,
                   std::size_t first) {
  for (std::size_t i = first; i < recipe.effects.size(); ++i) {
    recipe.effects[i]->extend(data, model, train);
    const Recipe so_far{recipe.given, {recipe.effects.begin(), recipe.effects.begin() + std::ptrdiff_t(i + 1)}};
    for (std::size_t s : train) adapt_strike(data, so_far, model, s);
  }
}

void name_effects(const Recipe& recipe, AuditModel& model) {
  model.effects.clear();
  for (const Effect* e : recipe.effects) model.effects.push_back(e->name);
}

// The model a recipe's effects extend: its given baseline, or one fitted on `train`.
AuditModel baseline_of(const AuditData& data, const Recipe& recipe, const std::vector<std::size_t>& train) {
  return recipe.given ? *recipe.given : fit_baseline(data, train);
}

// Whether `from` holds fold models of the first effects of `recipe` for `strikes` folds.
bool starts(const TrainedFolds& from, const Recipe& recipe, std::size_t strikes) {
  return from.models.size() == strikes && from.effects.size() <= recipe.effects.size() &&
         std::equal(from.effects.begin(), from.effects.end(), recipe.effects.begin());
}

}  // namespace

AuditModel fit_recipe(const AuditData& data, const Recipe& recipe, const std::vector<std::size_t>& train) {
  AuditModel model = baseline_of(data, recipe, train);
  extend_recipe(data, recipe, model, train, 0);
  name_effects(recipe, model);
  return model;
}

double cross_validated_gap(const AuditData& data, const Recipe& recipe, std::vector<AuditModel>* fold_models,
                           std::vector<double>* strike_gaps_db, const TrainedFolds* from, TrainedFolds* trained) {
  const std::size_t n = data.strike_count();
  if (fold_models) fold_models->clear();
  if (strike_gaps_db) strike_gaps_db->clear();
  if (trained) *trained = {recipe.effects, {}};
  if (n < 2) return in_sample_gap(data, recipe);
  const bool resume = from && starts(*from, recipe, n);
  // The folds stand alone: they run on the machine's cores, and are summed in order.
  std::vector<AuditModel> models(n), fitted(trained ? n : 0);
  std::vector<double> gaps(n);
  parallel_indices(n, [&](std::size_t k) {
    std::vector<std::size_t> train;
    for (std::size_t s = 0; s < n; ++s)
      if (s != k) train.push_back(s);
    models[k] = resume ? from->models[k] : baseline_of(data, recipe, train);
    extend_recipe(data, recipe, models[k], train, resume ? from->effects.size() : 0);
    if (trained) fitted[k] = models[k];
    name_effects(recipe, models[k]);
    adapt_strike(data, recipe, models[k], k);
    gaps[k] = strike_gap(models[k], data, k).gap_db;
  });
  double sum = 0.0;
  for (double g : gaps) sum += g;
  if (fold_models) *fold_models = std::move(models);
  if (strike_gaps_db) *strike_gaps_db = gaps;
  if (trained) trained->models = std::move(fitted);
  return sum / double(n);
}

AuditModel fit_last_effect(const AuditData& data, const Recipe& recipe, const AuditModel& before,
                           const std::optional<AuditModel>& extended) {
  const std::vector<std::size_t> all = all_strikes(data);
  AuditModel model = extended ? *extended : before;
  if (!extended) recipe.effects.back()->extend(data, model, all);
  for (std::size_t s : all) adapt_strike(data, recipe, model, s);
  name_effects(recipe, model);
  return model;
}

double in_sample_gap(const AuditData& data, const Recipe& recipe, AuditModel* fitted) {
  AuditModel model = fit_recipe(data, recipe, all_strikes(data));
  const double gap = mean_gap(model, data);
  if (fitted) *fitted = std::move(model);
  return gap;
}

}  // namespace ms::audit
