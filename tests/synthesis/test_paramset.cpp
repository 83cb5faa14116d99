// Parameter sets: the minimal form, every model source, overrides, the recipe hash, and one clear
// file:line:column error for each mistake a person can make.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/stimulus.hpp"

using namespace ms;

namespace {

const char* kMinimal = R"(sample_rate: 44100
duration_s: 2.0
modes:
  - {freq_hz: 440.0, decay_per_s: 3.0, amp: 1.0}
excitation: {type: impulse}
level: {normalize: none}
)";

const std::string kSupportBar = "duration_s: 1\nobject: {type: bar, length_m: 0.3, thickness_m: 0.01}\n"
                                "material: ren2013/wood\n";

ParamSet parse(const std::string& text, const std::vector<std::string>& sets = {}) {
  return parse_paramset(text, "set.yaml", ".", sets);
}

// The InputError message for `text`, or "" if it parsed.
std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parse(text, sets);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ParamSet, MinimalFormRendersTheFormulaExactly) {
  const ParamSet p = parse(kMinimal);
  EXPECT_EQ(p.sample_rate_hz, 44100);
  EXPECT_EQ(p.duration_s, 2.0);
  ASSERT_EQ(p.model.modes.size(), 1u);
  EXPECT_EQ(p.level.mode, LevelMode::none);
  const RenderedStimulus r = render_stimulus(p);
  ASSERT_EQ(r.audio.frames(), 88200u);
  EXPECT_EQ(r.level_gain, 1.0);
  double worst = 0;
  for (std::size_t n = 0; n < r.audio.frames(); ++n) {
    const double t = n / 44100.0;
    worst = std::max(worst, std::abs(r.audio.samples[n] - std::exp(-3.0 * t) * std::sin(2 * std::numbers::pi * 440 * t)));
  }
  EXPECT_LT(worst, 1e-5);
}

TEST(ParamSet, ModesFromCsvRelativeToTheSet) {
  test::TempDir dir;
  dir.write("m.csv", "freq_hz,decay_per_s,amp\n100,1,0.5\n200,2,0.25\n");
  const std::string path = dir.write("s.yaml", "duration_s: 0.5\nmodes: m.csv\n");
  const ParamSet p = load_paramset(path);
  ASSERT_EQ(p.model.modes.size(), 2u);
  EXPECT_EQ(p.model.modes[1].freq_hz, 200);
  EXPECT_EQ(p.level.mode, LevelMode::peak);  // default: peak at -1 dBFS
}

TEST(ParamSet, ObjectWithMaterialAndHitPoints) {
  const std::string text = R"(duration_s: 1
object: {type: bar, length_m: 0.3, thickness_m: 0.01, hit_position: 0.1, hit_points: {middle: 0.5}}
material: sterling2019/steel
)";
  const ParamSet p = parse(text);
  ASSERT_GT(p.model.modes.size(), 3u);
  for (const Mode& m : p.model.modes) EXPECT_LT(m.freq_hz, 22050.0);
  // f1 = 4.73^2/L^2 sqrt(E/rho h^2/12) / 2 pi with E/rho = 2.55e7 (damping shifts it negligibly).
  const double f1 = std::pow(4.73004074, 2) / 0.09 * std::sqrt(2.55e7 * 1e-4 / 12) / (2 * std::numbers::pi);
  EXPECT_NEAR(p.model.modes[0].freq_hz / f1, 1.0, 1e-6);
  // Struck in the middle, antisymmetric modes (2nd, 4th, ...) vanish.
  const ParamSet middle = parse(text + "hit: middle\n");
  EXPECT_LT(middle.model.modes[1].amp, 1e-9);
  EXPECT_GT(p.model.modes[1].amp, 0.1);
  EXPECT_NE(p.recipe_hash, middle.recipe_hash);
}

TEST(ParamSet, FundamentalAndSizeScaling) {
  const std::string base = R"(duration_s: 1
object: {type: plate, radius_m: 0.1, thickness_m: 0.003}
damping: {law: rayleigh, alpha1: 1.0, alpha2: 0.0}
)";
  const ParamSet tuned = parse(base + "fundamental_hz: 500\n");
  EXPECT_NEAR(std::hypot(2 * std::numbers::pi * tuned.model.modes[0].freq_hz, 0.5) / (2 * std::numbers::pi), 500.0, 1e-6);
  const ParamSet a = parse(base + "specific_modulus_m2_s2: 2.5e7\n");
  const ParamSet b = parse(base + "specific_modulus_m2_s2: 2.5e7\nsize_scale: 2\n");
  const double fa = std::hypot(2 * std::numbers::pi * a.model.modes[0].freq_hz, 0.5);
  const double fb = std::hypot(2 * std::numbers::pi * b.model.modes[0].freq_hz, 0.5);
  EXPECT_NEAR(fa / fb, 2.0, 1e-9);  // f ~ 1/s
}

TEST(ParamSet, HybridLawAndOverdampedWarning) {
  const std::string text = R"(duration_s: 1
object: {type: eigenvalues, lambda0: [1.0, 4.0, 1.0e6]}
damping: {law: rayleigh, alpha1: 0, alpha2: 0.5}
specific_modulus_m2_s2: 1.0e4
)";
  // lambda = 1e4, 4e4, 1e10; d = lambda/4: (2500)^2 > 1e4 -> all overdamped except none.
  const std::string msg = error_of(text);
  EXPECT_NE(msg.find("no modes"), std::string::npos) << msg;
  const ParamSet p = parse(R"(duration_s: 1
object: {type: eigenvalues, lambda0: [1.0, 100.0]}
damping: {law: rayleigh, alpha1: 0, alpha2: 1.0e-3}
specific_modulus_m2_s2: 1.0e6
)");  // lambda = 1e6 (d = 500, kept), 1e8 (d = 5e4, overdamped)
  ASSERT_EQ(p.model.modes.size(), 1u);
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_NE(p.warnings[0].find("overdamped"), std::string::npos);
  const ParamSet h = parse("duration_s: 1\nobject: {type: eigenvalues, lambda0: [1.0]}\n"
                           "material: sterling2019/glass\ndamping_law: hybrid\nfundamental_hz: 1000\n");
  EXPECT_NEAR(h.model.modes[0].decay_per_s,
              0.5 * (1.9 + 1.5e-7 * std::pow(2 * std::numbers::pi * 1000.0, 2 * 0.974)), 1e-9);
}

TEST(ParamSet, OverridesAndStableHash) {
  const ParamSet a = parse(kMinimal);
  // Same recipe written differently (order, comments, spacing) -> same hash.
  const ParamSet b = parse(R"(# a comment
level: {normalize: none}
excitation:
  type: impulse
modes: [{amp: 1.0, freq_hz: 440, decay_per_s: 3}]
duration_s: 2
sample_rate: 44100
)");
  EXPECT_EQ(a.recipe_hash, b.recipe_hash);
  EXPECT_EQ(a.recipe_hash.size(), 64u);
  const ParamSet c = parse(kMinimal, {"duration_s=1.5", "excitation.type=raised_cosine",
                                      "excitation.contact_s=0.001"});
  EXPECT_EQ(c.duration_s, 1.5);
  EXPECT_EQ(c.excitation.shape, PulseShape::raised_cosine);
  EXPECT_NE(a.recipe_hash, c.recipe_hash);
  const std::string msg = error_of(kMinimal, {"duration_s=abc"});
  EXPECT_NE(msg.find("--set duration_s"), std::string::npos) << msg;
  EXPECT_NE(error_of(kMinimal, {"novalue"}).find("key=value"), std::string::npos);
}

struct BadCase {
  const char* name;
  std::string text;
  const char* expected_location;  // "set.yaml:L:C"
  const char* expected_words;
};

TEST(ParamSet, EveryMistakeGetsOneLineWithLocation) {
  const BadCase cases[] = {
      {"syntax", "duration_s: 2\nmodes: [{freq_hz: 1\n", "set.yaml:3:1", "YAML syntax error"},
      {"unknown key", "duration_s: 2\ndurration: 3\nmodes: [{freq_hz: 1, decay_per_s: 1, amp: 1}]\n",
       "set.yaml:2:1", "did you mean 'duration_s'"},
      {"unknown mode key", "duration_s: 2\nmodes: [{freq_hz: 1, decay: 1, amp: 1}]\n", "set.yaml:2:22",
       "did you mean 'decay_per_s'"},
      {"wrong type", "duration_s: [1, 2]\nmodes: [{freq_hz: 1, decay_per_s: 1, amp: 1}]\n", "set.yaml:1:13",
       "expected a number"},
      {"text for number", "duration_s: two\nmodes: [{freq_hz: 1, decay_per_s: 1, amp: 1}]\n", "set.yaml:1:13",
       "expected a number"},
      {"nan", "duration_s: 1\nmodes: [{freq_hz: .nan, decay_per_s: 1, amp: 1}]\n", "set.yaml:2:19",
       "not a finite number"},
      {"inf", "duration_s: 1\nmodes: [{freq_hz: 100, decay_per_s: .inf, amp: 1}]\n", "set.yaml:2:37",
       "not a finite number"},
      {"negative decay", "duration_s: 1\nmodes: [{freq_hz: 100, decay_per_s: -1, amp: 1}]\n", "set.yaml:2:37",
       "must not be negative"},
      {"negative amp", "duration_s: 1\nmodes: [{freq_hz: 100, decay_per_s: 1, amp: -2}]\n", "set.yaml:2:45",
       "must not be negative"},
      {"empty model", "duration_s: 1\nmodes: []\n", "set.yaml:1:1", "no modes"},
      {"no model", "duration_s: 1\n", "set.yaml:1:1", "no model"},
      {"zero duration", "duration_s: 0\nmodes: [{freq_hz: 100, decay_per_s: 1, amp: 1}]\n", "set.yaml:1:13",
       "greater than 0"},
      {"absurd duration", "duration_s: 1e6\nmodes: [{freq_hz: 100, decay_per_s: 1, amp: 1}]\n",
       "set.yaml:1:13", "absurd duration"},
      {"bad sample rate", "sample_rate: 100\nduration_s: 1\nmodes: [{freq_hz: 10, decay_per_s: 1, amp: 1}]\n",
       "set.yaml:1:14", "8000"},
      {"missing csv", "duration_s: 1\nmodes: nowhere.csv\n", "set.yaml:2:8", "no such file"},
      {"unknown material", "duration_s: 1\nobject: {type: bar, length_m: 0.3, thickness_m: 0.01}\n"
                           "material: sterling2019/stel\n",
       "set.yaml:3:11", "did you mean 'sterling2019/steel'"},
      {"unknown object", "duration_s: 1\nobject: {type: sphere}\nmaterial: ren2013/wood\n", "set.yaml:2:16",
       "unknown object type"},
      {"contact too long", "duration_s: 1\nmodes: [{freq_hz: 100, decay_per_s: 1, amp: 1}]\n"
                           "excitation: {type: hertz, contact_s: 0.2}\n",
       "set.yaml:3:38", "not a strike"},
      {"impulse with contact", "duration_s: 1\nmodes: [{freq_hz: 100, decay_per_s: 1, amp: 1}]\n"
                               "excitation: {type: impulse, contact_s: 0.001}\n",
       "set.yaml:3:40", "no contact duration"},
      {"support contacts on listed modes", "duration_s: 1\nmodes: [{freq_hz: 100, decay_per_s: 1, amp: 1}]\n"
                                           "effects: {support_damping: {contacts: [0.5], mu: 0.3, c: 1}}\n",
       "set.yaml:3:39", "contacts need an object's mode shapes"},
      {"support contact key", kSupportBar + "effects: {support_damping: {contacts: [{positon: 0.5}], mu: 0.3, c: 1}}\n",
       "set.yaml:4:41", "did you mean 'position'"},
      {"support contact off the bar", kSupportBar + "effects: {support_damping: {contacts: [0.5, 1.5], mu: 0.3, c: 1}}\n",
       "set.yaml:4:45", "effects.support_damping.contacts[1]: must lie in [0, 1]"},
      {"support contact without c", kSupportBar + "effects: {support_damping: {contacts: [0.5], mu: 0.3}}\n",
       "set.yaml:4:40", "needs 'c'"},
      {"support contacts without mu", kSupportBar + "effects: {support_damping: {contacts: [0.5], c: 1}}\n",
       "set.yaml:4:28", "contacts need 'mu'"},
      {"support mu out of range", kSupportBar + "effects: {support_damping: {contacts: [0.5], mu: 1.5, c: 1}}\n",
       "set.yaml:4:50", "effects.support_damping.mu: must lie in [0, 1]"},
      {"support normal out of range",
       kSupportBar + "effects: {support_damping: {contacts: [{position: 0, normal_deg: 120}], mu: 0.3, c: 1}}\n",
       "set.yaml:4:66", "must lie in [0, 90] degrees"},
      {"support mu without contacts", kSupportBar + "effects: {support_damping: {extra_decay_per_s: 1, mu: 0.3}}\n",
       "set.yaml:4:55", "applies to 'contacts'"},
  };
  for (const BadCase& c : cases) {
    const std::string msg = error_of(c.text);
    EXPECT_EQ(msg.rfind(c.expected_location, 0), 0u) << c.name << ": " << msg;
    EXPECT_NE(msg.find(c.expected_words), std::string::npos) << c.name << ": " << msg;
  }
}

TEST(ParamSet, BadCsvCellNamesLineAndColumn) {
  test::TempDir dir;
  dir.write("m.csv", "freq_hz,decay_per_s,amp\n100,1,0.5\n200,oops,0.25\n");
  const std::string path = dir.write("s.yaml", "duration_s: 0.5\nmodes: m.csv\n");
  try {
    load_paramset(path);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("m.csv:3:5"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("decay_per_s"), std::string::npos) << e.what();
  }
  dir.write("n.csv", "freq_hz,amp\n100,0.5\n");
  const std::string path2 = dir.write("t.yaml", "duration_s: 0.5\nmodes: n.csv\n");
  try {
    load_paramset(path2);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing column 'decay_per_s'"), std::string::npos) << e.what();
  }
}

TEST(ParamSet, UnreadablePathsAreClear) {
  try {
    load_paramset("/nonexistent/set.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/set.yaml: no such file");
  }
  test::TempDir dir;
  EXPECT_THROW(load_paramset(dir.path().string()), InputError);  // a folder
}

TEST(ParamSet, PruneBlockAppliesTheMaskingRule) {
  // Two modes a Bark apart and a weak third next to the strong one: the third is masked at a_v = 16.
  const std::string base = R"(duration_s: 1
modes:
  - {freq_hz: 1000, decay_per_s: 5, amp: 1.0}
  - {freq_hz: 1010, decay_per_s: 5, amp: 0.01}
  - {freq_hz: 3000, decay_per_s: 5, amp: 0.5}
)";
  const ParamSet all = parse(base);
  const ParamSet masked = parse(base + "prune: {method: masking, threshold_db: 16, order: energy}\n");
  EXPECT_EQ(masked.modes_before_pruning, 3u);
  ASSERT_EQ(masked.model.modes.size(), 2u);
  EXPECT_EQ(masked.model.modes[0].freq_hz, 1000);  // energy order: strongest first
  EXPECT_EQ(masked.model.modes[1].freq_hz, 3000);
  EXPECT_NE(all.recipe_hash, masked.recipe_hash);
  const ParamSet first = parse(base + "prune: {method: energy, keep: 1}\n");
  ASSERT_EQ(first.model.modes.size(), 1u);
  EXPECT_EQ(first.model.modes[0].freq_hz, 1000);
  EXPECT_NE(error_of(base + "prune: {method: loud}\n").find("set.yaml:6:17: prune.method: unknown value 'loud'"),
            std::string::npos)
      << error_of(base + "prune: {method: loud}\n");
  EXPECT_NE(error_of(base + "prune: {threshold_db: 99}\n").find("prune.threshold_db"), std::string::npos);
  EXPECT_NE(error_of(base + "prune: {keep: 0}\n").find("at least 1"), std::string::npos);
}
