// `renderer: bandpass` with its `bandpass:` section and `phase: cosine` in a parameter set: what they
// read to, what they render, that they write back to the same recipe and hash, and their errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "synthesis/bandpass_bank.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/paramset_recipe.hpp"
#include "synthesis/stimulus.hpp"

using namespace ms;

namespace {

const std::string kTwoModes =
    "duration_s: 0.3\n"
    "modes: [{freq_hz: 440, decay_per_s: 3, amp: 1}, {freq_hz: 2500, decay_per_s: 20, amp: 0.5}]\n"
    "level: {normalize: none}\n";

ParamSet set(const std::string& text) { return resolve(read_recipe(text, "set.yaml", ".")); }

// The text write_yaml gives for `text`, after checking it reads back to itself and to the same hash.
std::string written(const std::string& text) {
  const ParamSetRecipe recipe = read_recipe(text, "set.yaml", ".");
  const std::string yaml = write_yaml(recipe);
  const ParamSetRecipe again = read_recipe(yaml, "written.yaml", ".");
  EXPECT_EQ(write_yaml(again), yaml) << text;
  EXPECT_EQ(resolve(again).recipe_hash, resolve(recipe).recipe_hash) << yaml;
  return yaml;
}

std::string error_of(const std::string& text) {
  try {
    set(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(ParamSetBandpass, RendersThroughTheBandPassBankWithTheStrikeGainAsTheImpulse) {
  const ParamSet p = set(kTwoModes + "excitation: {type: impulse, gain: 3}\nrenderer: bandpass\nbandpass: {q: 1200, clip: 0.5}\n");
  EXPECT_EQ(p.renderer, Renderer::bandpass);
  EXPECT_EQ(p.bandpass_q, std::vector<double>{1200.0});
  EXPECT_EQ(p.bandpass_clip, 0.5);
  const std::vector<float> y = render_stimulus(p).audio.samples;
  EXPECT_EQ(y, render_bandpass(p.model, {1200.0}, 3.0, 0.5, 44100.0, y.size()));
  EXPECT_NE(y, render_stimulus(set(kTwoModes)).audio.samples);  // not the resonator bank
}

TEST(ParamSetBandpass, QPerModeOrFromAMaterialInEitherOfTheThesisTables) {
  EXPECT_EQ(set(kTwoModes + "renderer: bandpass\nbandpass: {q: [800, 2000]}\n").bandpass_q,
            (std::vector<double>{800.0, 2000.0}));
  EXPECT_EQ(set(kTwoModes + "renderer: bandpass\nbandpass: {material: wood}\n").bandpass_q,
            std::vector<double>{1500.0});  // Table 4.1, the default
  EXPECT_EQ(set(kTwoModes + "renderer: bandpass\nbandpass: {material: metal, q_table: section_4_3_1_2}\n").bandpass_q,
            std::vector<double>{material_q(BandpassMaterial::metal, QTable::section_4_3_1_2)});
  const std::string a = set(kTwoModes + "renderer: bandpass\nbandpass: {material: wood}\n").recipe_hash;
  EXPECT_NE(a, set(kTwoModes + "renderer: bandpass\nbandpass: {material: glass}\n").recipe_hash);
  EXPECT_NE(a, set(kTwoModes).recipe_hash);
  EXPECT_EQ(a, set(kTwoModes + "renderer: bandpass\nbandpass: {q: 1500}\n").recipe_hash);  // the same sound
}

TEST(ParamSetBandpass, CosinePhaseStartsEveryModeAtItsAmplitude) {
  const ParamSet sine = set(kTwoModes), cosine = set(kTwoModes + "phase: cosine\n");
  for (const Mode& m : cosine.model.modes) EXPECT_DOUBLE_EQ(m.phase_rad, 0.5 * std::numbers::pi);
  EXPECT_NE(sine.recipe_hash, cosine.recipe_hash);
  const std::vector<float> ys = render_stimulus(sine).audio.samples, yc = render_stimulus(cosine).audio.samples;
  EXPECT_NEAR(ys[0], 0.0, 1e-6);
  EXPECT_NEAR(yc[0], 1.5, 1e-4);  // sum of the amplitudes: Eq 2.1's click-like onset
  EXPECT_NEAR(yc[100], 1.0 * std::exp(-3.0 * 100 / 44100.0) * std::cos(2 * std::numbers::pi * 440 * 100 / 44100.0) +
                           0.5 * std::exp(-20.0 * 100 / 44100.0) * std::cos(2 * std::numbers::pi * 2500 * 100 / 44100.0),
              1e-4);
}

TEST(ParamSetBandpass, TheNewKeysWriteBackToTheSameRecipe) {
  EXPECT_TRUE(contains(written(kTwoModes + "renderer: bandpass\nbandpass: {q: 1500}\n"),
                       "renderer: bandpass\nbandpass: {q: 1500}"));
  EXPECT_TRUE(contains(written(kTwoModes + "renderer: bandpass\nbandpass: {q: [800, 2000.5], clip: 0}\n"),
                       "bandpass: {q: [800, 2000.5], clip: 0}"));
  EXPECT_TRUE(contains(written(kTwoModes + "renderer: bandpass\nbandpass: {material: glass, q_table: section_4_3_1_2}\n"),
                       "bandpass: {material: glass, q_table: section_4_3_1_2}"));
  EXPECT_TRUE(contains(written(kTwoModes + "phase: cosine\n"), "phase: cosine"));
  const std::string plain = written(kTwoModes);
  EXPECT_FALSE(contains(plain, "renderer"));  // the defaults are left out
  EXPECT_FALSE(contains(plain, "phase"));
}

TEST(ParamSetBandpass, MistakesAreNamedWhereTheyWereWritten) {
  EXPECT_TRUE(contains(error_of(kTwoModes + "bandpass: {q: 1000}\n"), "set.yaml:4:"));
  EXPECT_TRUE(contains(error_of(kTwoModes + "bandpass: {q: 1000}\n"), "with 'renderer: bandpass' only"));
  EXPECT_TRUE(contains(error_of(kTwoModes + "renderer: bandpass\n"), "needs 'bandpass: {q: ...}'"));
  EXPECT_TRUE(contains(error_of(kTwoModes + "renderer: bandpas\n"), "bandpass"));  // the suggestion
  EXPECT_TRUE(contains(error_of(kTwoModes + "renderer: bandpass\nbandpass: {q: 1000, material: wood}\n"),
                       "either 'q' or 'material'"));
  EXPECT_TRUE(contains(error_of(kTwoModes + "renderer: bandpass\nbandpass: {q: [1, 2, 3]}\n"),
                       "3 Q values for 2 modes"));
  EXPECT_TRUE(contains(error_of(kTwoModes + "renderer: bandpass\nbandpass: {q: -5}\n"), "bandpass.q"));
  EXPECT_TRUE(contains(error_of(kTwoModes + "renderer: bandpass\nbandpass: {material: steel}\n"), "metal"));
  EXPECT_TRUE(contains(error_of(kTwoModes + "renderer: bandpass\nbandpass: {q: 9, q_table: table_4_1}\n"),
                       "give 'material' instead"));
  EXPECT_TRUE(contains(error_of(kTwoModes + "excitation: {type: hertz, contact_s: 0.001}\nrenderer: bandpass\n"
                                            "bandpass: {q: 9}\n"),
                       "excited by an impulse"));
  EXPECT_TRUE(contains(error_of(kTwoModes + "phase: tangent\n"), "cosine"));
}
