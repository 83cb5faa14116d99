// ParamSetRecipe: what read_recipe makes of each key, the line write_yaml writes for it, and that the
// written text reads back to the same recipe (the writer's fixed point) with the same recipe hash.
// The enum keys read, write and suggest through their name tables.
#include <gtest/gtest.h>

#include <string>

#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/paramset_recipe.hpp"

using namespace ms;

namespace {

const std::string kModes = "duration_s: 0.5\nmodes: [{freq_hz: 440, decay_per_s: 3, amp: 1}]\n";
const std::string kBar = "duration_s: 0.5\nmaterial: ren2013/wood\nobject: {type: bar, length_m: 0.3, thickness_m: 0.01}\n";

ParamSetRecipe read(const std::string& text, const std::string& base_dir = ".") {
  return read_recipe(text, "set.yaml", base_dir);
}

// Writes `text`'s recipe, checks the written text reads back to itself and to the same recipe hash,
// and returns it.
std::string written(const std::string& text, const std::string& base_dir = ".") {
  const ParamSetRecipe recipe = read(text, base_dir);
  const std::string yaml = write_yaml(recipe);
  const ParamSetRecipe again = read_recipe(yaml, "written.yaml", base_dir);
  EXPECT_EQ(write_yaml(again), yaml) << text;
  EXPECT_EQ(resolve(again).recipe_hash, resolve(recipe).recipe_hash) << yaml;
  return yaml;
}

std::string error_of(const std::string& text) {
  try {
    resolve(read(text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(ParamSetRecipe, ReadsEveryTopLevelKeyAsWritten) {
  const ParamSetRecipe r = read(
      "description: a bar\nsample_rate: 48000\nduration_s: 0.25\nmaterial: sterling2019/steel\n"
      "damping_law: hybrid\nspecific_modulus_m2_s2: 2.5e7\namp_scale: 2\nstiffness_scale: 1.5\nsize_scale: 0.5\n"
      "hit: tip\nobject: {type: bar, length_m: 0.3, thickness_m: 0.01, hit_points: {tip: 0.9}}\n");
  EXPECT_EQ(r.description, "a bar");
  EXPECT_EQ(r.sample_rate_hz, 48000);
  EXPECT_EQ(r.duration_s, 0.25);
  EXPECT_EQ(r.material, "sterling2019/steel");
  EXPECT_EQ(r.damping_law, MaterialFit::hybrid);
  EXPECT_EQ(r.specific_modulus_m2_s2, 2.5e7);
  EXPECT_EQ(r.amp_scale, 2.0);
  EXPECT_EQ(r.stiffness_scale, 1.5);
  EXPECT_EQ(r.size_scale, 0.5);
  EXPECT_EQ(r.hit, "tip");
  ASSERT_TRUE(r.object.has_value());
  EXPECT_EQ(r.object->type, ObjectType::bar);
  ASSERT_EQ(r.object->hit_points.size(), 1u);
  EXPECT_EQ(r.object->hit_points[0].name, "tip");
  EXPECT_EQ(r.object->hit_points[0].position, 0.9);
  // Nothing is resolved yet: no material is looked up, no mode built.
  EXPECT_TRUE(r.modes.empty());
  EXPECT_FALSE(r.fundamental_hz.has_value());
}

TEST(ParamSetRecipe, WritesEachKeyOnItsLine) {
  struct Case {
    std::string yaml, line;
  };
  const std::vector<Case> cases = {
      {"description: 'a \"quoted\": text'\n" + kModes, "description: \"a \\\"quoted\\\": text\""},
      {"sample_rate: 48000\n" + kModes, "sample_rate: 48000"},
      {"duration_s: 0.30000000000000004\nmodes: [{freq_hz: 440, decay_per_s: 3, amp: 1}]\n",
       "duration_s: 0.30000000000000004"},
      {"duration_s: 1\nmodes: [{freq_hz: 440.5, decay_per_s: 0, amp: 0.25, phase_rad: 1.5}]\n",
       "  - {freq_hz: 440.5, decay_per_s: 0, amp: 0.25, phase_rad: 1.5}"},
      {kModes + "amp_scale: 2\nstiffness_scale: 1.5\nsize_scale: 0.5\n", "amp_scale: 2\nstiffness_scale: 1.5\nsize_scale: 0.5"},
      {kModes + "hit_gains: {tip: [0.5]}\nhit: tip\n", "hit_gains:\n  tip: [0.5]\nhit: tip"},
      {kBar, "object:\n  type: bar\n  length_m: 0.3\n  thickness_m: 0.01\nmaterial: ren2013/wood"},
      {"duration_s: 0.5\nmaterial: ren2013/wood\nobject: {type: bar, length_m: 0.3, thickness_m: 0.01, "
       "hit_position: 0.2, hit_points: {tip: 0.9, mid: 0.5}, max_modes: 10}\n",
       "  hit_position: 0.2\n  hit_points: {tip: 0.9, mid: 0.5}\n  max_modes: 10"},
      {"duration_s: 0.5\nmaterial: ren2013/glass\nobject: {type: plate, radius_m: 0.1, thickness_m: 0.002, "
       "poisson: 0.22, hit_radius: 0.5}\n",
       "  type: plate\n  radius_m: 0.1\n  thickness_m: 0.002\n  poisson: 0.22\n  hit_radius: 0.5"},
      {"duration_s: 0.5\nobject: {type: eigenvalues, lambda0: [1, 2.7], gains: [1, 0.5]}\nfundamental_hz: 300\n"
       "damping: {law: constant_q, loss_factor: 0.01}\n",
       "  type: eigenvalues\n  lambda0: [1, 2.7]\n  gains: [1, 0.5]\ndamping: {law: constant_q, loss_factor: 0.01}\n"
       "fundamental_hz: 300"},
      {"duration_s: 0.5\nobject: {type: eigenvalues, lambda0: [1]}\nspecific_modulus_m2_s2: 2.5e7\n"
       "damping: {law: hybrid, alpha1: 2, alpha2: 1e-7, alpha3: 0.7}\n",
       "damping: {law: hybrid, alpha1: 2, alpha2: 1e-07, alpha3: 0.7}\nspecific_modulus_m2_s2: 2.5e+07"},
      {"duration_s: 0.5\nmaterial: sterling2019/wood\nobject: {type: bar, length_m: 0.3, thickness_m: 0.01}\n"
       "damping_law: hybrid\n",
       "material: sterling2019/wood\ndamping_law: hybrid"},
      {kModes + "excitation: {type: raised_cosine, contact_s: 0.001, gain: 2}\n",
       "excitation: {type: raised_cosine, contact_s: 0.001, gain: 2}"},
      {kModes + "effects: {support_damping: {extra_decay_per_s: 1, per_mode_decay_per_s: [2], "
                "exponential_mean_per_s: 3, seed: 4}}\n",
       "effects:\n  support_damping: {extra_decay_per_s: 1, per_mode_decay_per_s: [2], exponential_mean_per_s: 3, seed: 4}"},
      {kBar + "effects: {support_damping: {contacts: [0.5, {position: 0, c: 4, normal_deg: 90}, {position: 1, c: 2}], "
              "mu: 0.3, c: 10, exponential_mean_per_s: 1, seed: 2}}\n",
       "  support_damping: {exponential_mean_per_s: 1, seed: 2, contacts: [0.5, {position: 0, c: 4, normal_deg: 90}, "
       "{position: 1, c: 2}], mu: 0.3, c: 10}"},
      {"duration_s: 0.5\nmaterial: ren2013/glass\nobject: {type: plate, radius_m: 0.1, thickness_m: 0.002}\n"
       "effects: {support_damping: {contacts: [{position: 0.999, c: 1e-3}], mu: 0}}\n",
       "  support_damping: {contacts: [{position: 0.999, c: 0.001}], mu: 0}"},
      {kModes + "effects: {doublets: {split_rel: 0.01, balance: 0.25, min_order: 0}}\n",
       "  doublets: {split_rel: 0.01, balance: 0.25, min_order: 0}"},
      {kModes + "effects: {doublets: {split_hz: 2}}\n", "  doublets: {split_hz: 2}"},
      {kModes + "effects: {noise: {snr_db: 40, seed: -1}}\n", "  noise: {snr_db: 40, seed: -1}"},
      {kModes + "effects: {reverb: {rt60_s: 0.6, level_db: -25}}\n", "  reverb: {rt60_s: 0.6, level_db: -25, seed: 0}"},
      {kModes + "effects: {transient: {level_db: -15, duration_ms: 5, seed: 3}}\n",
       "  transient: {level_db: -15, duration_ms: 5, seed: 3}"},
      {kModes + "prune: {method: masking, threshold_db: 10, playback_db: 60, combine: sum, order: loudness, keep: 1}\n",
       "prune: {method: masking, threshold_db: 10, playback_db: 60, combine: sum, order: loudness, keep: 1}"},
      {kModes + "level: {normalize: attack_rms, target_dbfs: -30, attack_window_s: 0.01}\n",
       "level: {normalize: attack_rms, target_dbfs: -30, attack_window_s: 0.01}"},
      {kModes + "level: {normalize: attack_rms}\n", "level: {normalize: attack_rms}\n"},
      {kModes + "output: {format: pcm24}\n", "output: {format: pcm24}"},
  };
  for (const Case& c : cases) {
    const std::string yaml = written(c.yaml);
    EXPECT_TRUE(has(yaml, c.line)) << "expected\n" << c.line << "\nin\n" << yaml;
  }
}

TEST(ParamSetRecipe, DefaultsAreLeftOutAndReadBackTheSame) {
  const std::string yaml = written(kModes);
  EXPECT_EQ(yaml,
            "sample_rate: 44100\nduration_s: 0.5\nmodes:\n  - {freq_hz: 440, decay_per_s: 3, amp: 1}\n"
            "excitation: {type: impulse}\nlevel: {normalize: peak}\noutput: {format: float32}\n");
  // Written defaults read as the defaults: the same recipe, the same text.
  EXPECT_EQ(written(kModes + "level: {normalize: peak, target_dbfs: -1, attack_window_s: 0.005}\n"
                             "excitation: {type: impulse, gain: 1}\nsample_rate: 44100\n"),
            yaml);
}

TEST(ParamSetRecipe, FilesAreWrittenAsNamedAndReadFromTheSameFolder) {
  test::TempDir dir;
  dir.write("sets/m.csv", "freq_hz,decay_per_s,amp\n500,4,1\n");
  dir.write("sets/materials/spoon.yaml", "id: spoon\nrayleigh: {alpha1_per_s: 5, alpha2_s: 1e-7}\n"
                                         "specific_modulus_m2_s2: 2.5e7\namp_scale: 1\n");
  const std::string base = dir.file("sets");
  EXPECT_TRUE(has(written("duration_s: 0.5\nmodes: m.csv\n", base), "modes: m.csv\n"));
  EXPECT_TRUE(has(written("duration_s: 0.5\nmaterial: {file: materials/spoon.yaml}\n"
                          "object: {type: bar, length_m: 0.3, thickness_m: 0.01}\n", base),
                  "material: {file: materials/spoon.yaml}"));
}

TEST(ParamSetRecipe, OverridesAreWrittenAsPartOfTheRecipe) {
  const ParamSetRecipe r = read_recipe(kModes, "set.yaml", ".", {"effects.noise.snr_db=30", "hit_gains.a=[0.5]"});
  EXPECT_TRUE(r.noise.enabled);
  EXPECT_EQ(r.noise.snr_db, 30.0);
  const std::string yaml = write_yaml(r);
  EXPECT_TRUE(has(yaml, "noise: {snr_db: 30, seed: 0}")) << yaml;
  EXPECT_EQ(resolve(read(yaml)).recipe_hash, resolve(r).recipe_hash);
}

// Every name of every enum-valued key is read and written through its table.
TEST(ParamSetRecipe, EveryEnumNameReadsAndWritesBack) {
  for (const auto& e : kPulseShapeNames) {
    const std::string contact = e.value == PulseShape::impulse ? "" : ", contact_s: 0.001";
    const std::string line = "excitation: {type: " + std::string(e.name) + contact + "}";
    EXPECT_TRUE(has(written(kModes + line + "\n"), line));
  }
  for (const auto& e : kLevelModeNames) {
    const std::string line = "level: {normalize: " + std::string(e.name) + "}";
    EXPECT_TRUE(has(written(kModes + line + "\n"), line));
  }
  for (const auto& e : kSampleFormatNames) {
    const std::string line = "output: {format: " + std::string(e.name) + "}";
    EXPECT_TRUE(has(written(kModes + line + "\n"), line));
  }
  for (const auto& e : kPruneMethodNames) EXPECT_EQ(read(kModes + "prune: {method: " + std::string(e.name) + "}\n").prune->options.method, e.value);
  for (const auto& e : kModeOrderNames) EXPECT_EQ(read(kModes + "prune: {order: " + std::string(e.name) + "}\n").prune->options.order, e.value);
  for (const auto& e : kMaskingCombineNames)
    EXPECT_EQ(read(kModes + "prune: {combine: " + std::string(e.name) + "}\n").prune->options.combine, e.value);
  for (const auto& e : kDampingKindNames) {
    const std::string law = "damping: {law: " + std::string(e.name) + ", alpha1: 1, alpha2: 1e-7, loss_factor: 0.001}";
    const ParamSetRecipe r = read("duration_s: 0.5\nobject: {type: eigenvalues, lambda0: [1e6]}\nfundamental_hz: 300\n" + law + "\n");
    EXPECT_EQ(r.damping->kind, e.value);
    EXPECT_TRUE(has(write_yaml(r), "damping: {law: " + std::string(e.name)));
  }
  for (const auto& e : kMaterialFitNames) EXPECT_EQ(read(kBar + "damping_law: " + std::string(e.name) + "\n").damping_law, e.value);
  for (const auto& e : kObjectTypeNames) EXPECT_NE(std::string(e.name), "?");
}

TEST(ParamSetRecipe, MisspelledNamesAreSuggestedFromTheTable) {
  EXPECT_TRUE(has(error_of(kModes + "prune: {method: loudnes}\n"),
                  "set.yaml:3:17: prune.method: unknown value 'loudnes' (expected masking, naive, energy or loudness; "
                  "did you mean 'loudness'?)"));
  EXPECT_TRUE(has(error_of(kModes + "excitation: {type: raised_cosin, contact_s: 0.001}\n"),
                  "did you mean 'raised_cosine'?"));
  EXPECT_TRUE(has(error_of(kModes + "output: {format: pcm42}\n"), "did you mean 'pcm24'?"));
  EXPECT_TRUE(has(error_of(kModes + "level: {normalize: attack}\n"), "(expected none, peak or attack_rms"));
  EXPECT_TRUE(has(error_of("duration_s: 0.5\nmaterial: ren2013/wood\nobject: {type: bars}\n"),
                  "unknown object type 'bars' (expected bar, plate or eigenvalues; did you mean 'bar'?)"));
  EXPECT_TRUE(has(error_of(kBar + "damping_law: hybird\n"), "set.yaml:4:14: damping_law: unknown damping_law 'hybird'"));
}

// What only resolving can find is still located at its key.
TEST(ParamSetRecipe, ResolveErrorsNameTheKey) {
  EXPECT_EQ(error_of(kBar + "hit: tipp\n"), "set.yaml:4:6: hit: unknown hit point 'tipp'");
  EXPECT_EQ(error_of(kModes + "hit_gains: {a: [1, 2]}\n"), "set.yaml:3:16: hit_gains.a: needs one gain per mode (1)");
  EXPECT_EQ(error_of("duration_s: 0.5\nmaterial: ren2013/wod\nobject: {type: bar, length_m: 0.3, thickness_m: 0.01}\n"),
            "set.yaml:2:11: material: unknown material 'ren2013/wod' (did you mean 'ren2013/wood'?)");
  EXPECT_EQ(error_of(kBar + "damping_law: hybrid\n"), "set.yaml:4:14: damping_law: ren2013/wood has no hybrid fit");
}

}  // namespace
