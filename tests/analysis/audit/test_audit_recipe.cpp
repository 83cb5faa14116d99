// The audit's augmented model is a ParamSetRecipe: its effects are the synthesis types, and its YAML
// (write_yaml) reads back to the same recipe and recipe hash.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/audit/audit.hpp"
#include "analysis/audit/augmented_paramset.hpp"
#include "analysis/audit/hidden_effect_generator.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/paramset_recipe.hpp"

namespace ms::audit {
namespace {

TEST(AuditRecipe, EffectsAreTheSynthesisTypesAndTheYamlReadsBack) {
  const HiddenCase hc = generate_hidden_case(77, {}, {});
  const AuditData data = make_audit_data(hc.recordings);
  AuditModel m = run_audit(data).final_model;
  ASSERT_FALSE(m.modes.empty());
  m.modes[0].doublet = {.split_hz = 2.0, .balance = 0.25};
  m.reverb = {.rt60_s = 0.6, .level_db = -25.0, .enabled = true};
  m.transient = {.level_db = -15.0, .duration_ms = 5.0, .enabled = true};
  const std::string description = "fitted to \"case\": 5 strikes";
  const ParamSetRecipe recipe = augmented_recipe(data, m, description);
  EXPECT_EQ(recipe.description, description);
  EXPECT_EQ(recipe.sample_rate_hz, data.measured.sample_rate_hz);
  // The doublet is both of its modes, their energy the merged mode's.
  const std::size_t below_nyquist = std::size_t(std::count_if(m.modes.begin(), m.modes.end(), [&](const AuditMode& a) {
    return a.freq_hz < 0.5 * data.measured.sample_rate_hz;
  }));
  ASSERT_EQ(recipe.modes.size(), below_nyquist + 1);
  const double f0 = m.modes[0].freq_hz, a0 = m.modes[0].amp * m.gain[representative_strike(m)];
  EXPECT_DOUBLE_EQ(recipe.modes[0].freq_hz, f0 - 1.0);
  EXPECT_DOUBLE_EQ(recipe.modes[1].freq_hz, f0 + 1.0);
  EXPECT_NEAR(std::hypot(recipe.modes[0].amp, recipe.modes[1].amp), a0, 1e-12 * a0);
  EXPECT_NEAR(recipe.modes[1].amp / recipe.modes[0].amp, 0.25 / 0.75, 1e-12);
  // Effects keep their values; the seeds are distinct so the noises are uncorrelated.
  EXPECT_EQ(recipe.reverb.rt60_s, 0.6);
  EXPECT_EQ(recipe.transient.duration_ms, 5.0);
  EXPECT_NE(recipe.reverb.seed, recipe.transient.seed);
  EXPECT_EQ(recipe.level.mode, LevelMode::none);
  const std::string yaml = augmented_paramset_yaml(data, m, description);
  EXPECT_EQ(yaml, write_yaml(recipe));
  const ParamSetRecipe again = read_recipe(yaml, "model.yaml", ".");
  EXPECT_EQ(again.description, description);
  EXPECT_EQ(write_yaml(again), yaml);
  EXPECT_EQ(resolve(again).recipe_hash, resolve(recipe).recipe_hash);
}

}  // namespace
}  // namespace ms::audit
