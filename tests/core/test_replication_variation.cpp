// Skandalou & Ireland 2017, Exp. 2 (protocols/skandalou2017_variation.yaml): per object and method a
// bipolar pair [single, variation] of five-strike bounce sequences, the variation striking two areas
// and the single sound the first area every time, at the same onsets and gains; the real cymbal's
// sequences are the hydrogen-drumkits strikes summed at the onsets; the export and one `stats ab` call
// give Fig. 5.3's mean and sd per object and method, + for variation.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core_fixtures.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {
namespace {

const std::string kProtocol = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/skandalou2017_variation.yaml";

Protocol load() {
  std::vector<std::string> problems;
  Protocol p = load_protocol(kProtocol, &problems);
  EXPECT_TRUE(problems.empty()) << problems.front();
  return p;
}

const StimulusSource& stimulus(const Protocol& p, const std::string& name) {
  const StimulusSource* s = p.find_stimulus(name);
  if (!s) throw std::runtime_error("no stimulus " + name);
  return *s;
}

std::string factor(const StimulusSource& s, const std::string& key) {
  for (const auto& [k, v] : s.factors)
    if (k == key) return v;
  return "";
}

TEST(ReplicationVariation, KeepsTheThesisDesign) {
  EXPECT_TRUE(check_protocol_file(kProtocol).problems.empty());
  const Protocol p = load();
  const Block* b = p.find_block("variation");
  ASSERT_NE(b, nullptr);
  const auto& ab = std::get<AbBlock>(b->body);
  EXPECT_EQ(ab.mode, AbMode::bipolar);
  EXPECT_TRUE(ab.references.empty());  // "two sounds and no reference"
  EXPECT_TRUE(b->randomize);
  ASSERT_EQ(ab.pairs.size(), 16u);  // 5 objects x 3 methods + the real cymbal's recordings
  std::map<std::string, std::set<std::string>> methods;
  for (const StimulusPair& pair : ab.pairs) {
    const StimulusSource &one = stimulus(p, pair[0].name), &var = stimulus(p, pair[1].name);
    // Written [single, variation]: + means variation preferred (Table 5.4).
    EXPECT_EQ(factor(one, "sound"), "single") << pair[0].name;
    EXPECT_EQ(factor(var, "sound"), "variation") << pair[1].name;
    for (const char* k : {"object", "material", "method"}) EXPECT_EQ(factor(one, k), factor(var, k)) << pair[0].name << k;
    methods[factor(one, "object")].insert(factor(one, "method"));
    ASSERT_EQ(one.kind, StimulusKind::sequence);
    ASSERT_EQ(var.kind, StimulusKind::sequence);
    ASSERT_EQ(one.sequence.size(), 5u);
    ASSERT_EQ(var.sequence.size(), 5u);
    std::set<std::string> single_parts, variation_parts;
    for (std::size_t i = 0; i < 5; ++i) {
      // The same bounce: onsets and gains strike for strike.
      EXPECT_EQ(one.sequence[i].onset_s, var.sequence[i].onset_s);
      EXPECT_EQ(one.sequence[i].gain_db, var.sequence[i].gain_db);
      single_parts.insert(one.sequence[i].stimulus.name);
      variation_parts.insert(var.sequence[i].stimulus.name);
      // Each strike is the object by the pair's method: rec-/bpf-/sin-<object>-<area>.
      EXPECT_EQ(var.sequence[i].stimulus.name.substr(0, 4), pair[1].name.substr(4, 4)) << pair[1].name;
    }
    EXPECT_EQ(single_parts.size(), 1u) << pair[0].name;      // one sound repeated
    EXPECT_EQ(variation_parts.size(), 2u) << pair[1].name;   // two areas
    EXPECT_EQ(one.sequence[0].stimulus.name, var.sequence[0].stimulus.name);  // the same first strike
    EXPECT_TRUE(variation_parts.count(*single_parts.begin())) << pair[1].name;
  }
  const std::set<std::string> three{"recording", "filter-based", "sinusoidal"};
  for (const char* object : {"plastic-bowl", "wood-cutting-board", "ceramic-plate", "glass-bottle", "metal-wok"})
    EXPECT_EQ(methods[object], three) << object;
  EXPECT_EQ(methods["cymbal"], std::set<std::string>{"recording"});
  // A bounce with restitution 0.7: each interval and each impact speed 0.7 of the previous one.
  const auto& s = stimulus(p, "var-rec-metal-wok").sequence;
  for (std::size_t i = 2; i < 5; ++i)
    EXPECT_NEAR((s[i].onset_s - s[i - 1].onset_s) / (s[i - 1].onset_s - s[i - 2].onset_s), 0.7, 0.002);
  for (std::size_t i = 1; i < 5; ++i) EXPECT_NEAR(s[i].gain_db - s[i - 1].gain_db, 20 * std::log10(0.7), 0.05);
  // The real object: the kit's Paiste ride on its bow and on its bell.
  EXPECT_EQ(stimulus(p, "rec-cymbal-bow").path, "audio/hydrogen-drumkits/PaisteRide-Med.wav");
  EXPECT_EQ(stimulus(p, "rec-cymbal-bell").path, "audio/hydrogen-drumkits/PaisteBell-Med.wav");
}

// The cymbal's variation sound is the two real strikes summed at the bounce's onsets and gains, and no
// sequence of the protocol reaches full scale.
TEST(ReplicationVariation, TheSequencesAreTheStrikesAtTheirOnsetsBelowFullScale) {
  const Protocol p = load();
  StimulusCache cache(p, "");
  const std::string dir = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/audio/hydrogen-drumkits/";
  const std::vector<float> bow = read_audio(dir + "PaisteRide-Med.wav").samples;
  const std::vector<float> bell = read_audio(dir + "PaisteBell-Med.wav").samples;
  const StimulusSource& var = stimulus(p, "var-rec-cymbal");
  std::vector<double> expected;
  for (const SequencePart& part : var.sequence) {
    const std::vector<float>& x = part.stimulus.name == "rec-cymbal-bow" ? bow : bell;
    const std::size_t at = std::size_t(std::llround(part.onset_s * 44100));
    expected.resize(std::max(expected.size(), at + x.size()), 0.0);
    for (std::size_t n = 0; n < x.size(); ++n) expected[at + n] += std::pow(10.0, part.gain_db / 20) * x[n];
  }
  const Samples got = cache.samples("var-rec-cymbal");
  ASSERT_EQ(got->size(), expected.size());
  for (std::size_t n = 0; n < expected.size(); ++n) ASSERT_NEAR((*got)[n], expected[n], 1e-7) << n;
  for (const StimulusSource& s : p.stimuli) {
    if (s.kind != StimulusKind::sequence) continue;
    float peak = 0.0f;
    for (float v : *cache.samples(s.name)) peak = std::max(peak, std::abs(v));
    EXPECT_LT(peak, 0.5f) << s.name;  // measured: -7.0 dBFS at most (the sinusoidal bowl)
    EXPECT_GT(peak, 0.05f) << s.name;
  }
}

TEST(ReplicationVariation, Figure53IsOneCallOnTheExport) {
  test::TempDir dir;
  const AutopilotOptions o = testing::shipped_study("skandalou2017_variation.yaml", dir);
  ASSERT_TRUE(testing::run_participants_and_export(o, 3, "L", 70, dir.file("out")));
  const TidyCsv t = TidyCsv::read(dir.file("out/ab.csv"));
  ASSERT_EQ(t.rows(), 48u);  // 3 listeners x 16 pairs
  std::map<std::string, std::vector<double>> cells;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const auto at = [&](const char* c) { return t.cell(r, t.column(c)); };
    EXPECT_EQ(at("pair_first").substr(0, 4), "one-") << r;
    EXPECT_EQ(at("pair_second").substr(0, 4), "var-") << r;
    EXPECT_EQ(at("sound"), "") << r;  // single against variation: no shared level
    const double played = t.number(r, t.column("response")), oriented = t.number(r, t.column("response_oriented"));
    EXPECT_EQ(oriented, at("swapped") == "1" ? -played : played) << r;
    cells[at("object") + "/" + at("method")].push_back(oriented);
  }
  ASSERT_EQ(cells.size(), 16u);
  const auto r = test::run_cli("stats ab " + dir.file("out/ab.csv") + " --task preference --score response_oriented "
                               "--by object,method --where block=variation --options single,variation --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["groups"].size(), 16u);
  for (const auto& g : j["groups"]) {
    const std::vector<double>& v = cells.at(g["group"].get<std::string>());
    double mean = 0, squares = 0;
    for (double x : v) mean += x / double(v.size());
    for (double x : v) squares += (x - mean) * (x - mean);
    EXPECT_EQ(g["score"]["n"], 3) << g["group"];
    EXPECT_NEAR(g["score"]["mean"].get<double>(), mean, 1e-12) << g["group"];
    EXPECT_NEAR(g["score"]["sd"].get<double>(), std::sqrt(squares / 2), 1e-12) << g["group"];
  }
  const auto text = test::run_cli("stats ab " + dir.file("out/ab.csv") + " --task preference --score response_oriented "
                                  "--by object,method --where block=variation --options single,variation", dir);
  EXPECT_NE(text.out.find("+ favours variation, - favours single; 16 group(s)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("cymbal/recording"), std::string::npos) << text.out;
}

}  // namespace
}  // namespace ms
