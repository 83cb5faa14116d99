// `modalstudy audit` and `audit-generate` end to end: a generated case with a hidden effect is named
// in the JSON, --report writes the pictures and a model.yaml that `modalstudy synth` renders, and
// bad input (different sample rates, silence, one strike, another object's model) exits 2 with one
// line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"

namespace fs = std::filesystem;

namespace ms::test {
namespace {

std::string strikes(const TempDir& d, const std::string& sub, int n) {
  std::string s;
  for (int i = 1; i <= n; ++i) s += " " + d.file(sub + "/strike" + std::to_string(i) + ".wav");
  return s;
}

TEST(AuditCli, GenerateThenAuditNamesTheHiddenEffectAndWritesAReport) {
  TempDir d;
  const RunResult g = run_cli("audit-generate --seed 31 --effects damping_law --strength 0.6 -o " + d.file("case"), d);
  ASSERT_EQ(g.exit_code, 0) << g.err;
  const auto hidden = nlohmann::json::parse(std::ifstream(d.file("case/hidden.json")));
  EXPECT_EQ(hidden["effects"][0], "damping_law");
  const RunResult r = run_cli("audit --measured" + strikes(d, "case", 5) + " --json --report " + d.file("report"), d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["named_effects"].size(), 1u) << r.out;
  EXPECT_EQ(j["named_effects"][0]["effect"], "damping_law");
  EXPECT_LT(j["gap_after"].get<double>(), 0.5 * j["gap_before"].get<double>());
  EXPECT_NEAR(j["named_effects"][0]["parameters"]["alpha3"].get<double>(), 1.0, 0.6);
  EXPECT_NE(j["named_effects"][0]["evidence"].get<std::string>().find("hybrid"), std::string::npos);
  // The repeatability floor: these strikes differ only by their gain, so almost all of the held-out
  // gap lies above it, and the law closes at least half of that (its share is the whole audit's).
  const double floor_db = j["floor_db"].get<double>();
  EXPECT_GE(floor_db, 0.0);
  EXPECT_LT(floor_db, 0.1);
  EXPECT_GE(j["share_above_floor"].get<double>(), 0.5);
  EXPECT_NEAR(j["named_effects"][0]["share_above_floor"].get<double>(), j["share_above_floor"].get<double>(), 1e-9);
  EXPECT_NEAR(j["share_above_floor"].get<double>(),
              (j["cv_gap_before"].get<double>() - j["cv_gap_after"].get<double>()) /
                  (j["cv_gap_before"].get<double>() - floor_db),
              1e-9);
  // The decision trail: one round per named effect plus the last, where nothing passed; the first is
  // also given alone, and in it damping_law passed its detector.
  ASSERT_EQ(j["rounds"].size(), 2u) << r.out;
  EXPECT_EQ(j["rounds"][0], j["first_round"]);
  bool law_passed = false;
  for (const auto& c : j["first_round"]) law_passed |= c["effect"] == "damping_law" && c["detector_passes"].get<bool>();
  EXPECT_TRUE(law_passed);
  // Locate: per-strike gaps and per-mode residuals of every strike; a hidden law shows in the decays.
  ASSERT_EQ(j["locate"]["strikes"].size(), 5u);
  for (const auto& st : j["locate"]["strikes"]) EXPECT_GE(st["floor"].get<double>(), 0.0);
  ASSERT_GE(j["locate"]["mode_residuals"].size(), 5u * 8u);
  double worst_decay = 0.0;
  for (const auto& m : j["locate"]["mode_residuals"]) worst_decay = std::max(worst_decay, std::abs(m["decay_rel"].get<double>()));
  EXPECT_GT(worst_decay, 0.05);
  EXPECT_LT(j["locate"]["strike_variation_db"].get<double>(), 0.1);
  for (const char* f : {"residual_before.png", "residual_after.png", "mode_amplitude_residuals.png",
                        "mode_decay_residuals.png", "damping.png", "gap_per_strike.png", "model.yaml", "audit.json"})
    EXPECT_GT(fs::file_size(d.file(std::string("report/") + f)), 100u) << f;
  const RunResult s = run_cli("synth " + d.file("report/model.yaml") + " -o " + d.file("improved.wav"), d);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_EQ(read_audio(d.file("improved.wav")).sample_rate_hz, 44100.0);
  // The improved model audited as --model: nothing left to name.
  const RunResult again = run_cli("audit --measured" + strikes(d, "case", 5) + " --model " + d.file("report/model.yaml") + " --json", d);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const auto j2 = nlohmann::json::parse(again.out);
  EXPECT_LT(j2["gap_before"].get<double>(), 1.5 * j["gap_after"].get<double>() + 0.3);
}

// Beside hand damping each held-out strike keeps its own decays, so a law there is named on its own
// test (the decays' lower edge bends), and the output says so instead of a share of the gap.
TEST(AuditCli, ALawBesideAHandIsNamedOnItsOwnTest) {
  TempDir d;
  const RunResult g = run_cli("audit-generate --seed 3 --effects support_damping,damping_law --strength 0.6,0.6 -o " +
                              d.file("case"), d);
  ASSERT_EQ(g.exit_code, 0) << g.err;
  const RunResult r = run_cli("audit --measured" + strikes(d, "case", 5) + " --json", d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["named_effects"].size(), 2u) << r.out;
  EXPECT_EQ(j["named_effects"][0]["effect"], "support_damping");
  EXPECT_FALSE(j["named_effects"][0]["named_on_own_test"].get<bool>());
  EXPECT_EQ(j["named_effects"][1]["effect"], "damping_law");
  EXPECT_TRUE(j["named_effects"][1]["named_on_own_test"].get<bool>());
  EXPECT_NE(j["named_effects"][1]["evidence"].get<std::string>().find("lower edge bends"), std::string::npos);
  const RunResult text = run_cli("audit --measured" + strikes(d, "case", 5), d);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  const std::size_t law = text.out.find("+ damping_law");
  ASSERT_NE(law, std::string::npos) << text.out;
  EXPECT_NE(text.out.find("named on its own test", law), std::string::npos) << text.out;
}

// Clean strikes with independent per-mode jitter: nothing named, and the audit says nothing the strikes
// share is missing rather than that its catalog fell short.
TEST(AuditCli, CleanJitteredStrikesShareNothingTheModelLacks) {
  TempDir d;
  const RunResult g = run_cli("audit-generate --seed 32 --jitter-db 2 -o " + d.file("case"), d);
  ASSERT_EQ(g.exit_code, 0) << g.err;
  const RunResult r = run_cli("audit --measured" + strikes(d, "case", 5) + " --report " + d.file("report"), d);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("nothing named, and nothing the strikes share is missing"), std::string::npos) << r.out;
  const auto json = nlohmann::json::parse(std::ifstream(d.file("report/audit.json")));
  EXPECT_TRUE(json["named_effects"].empty());
  EXPECT_FALSE(json["left_shared"]["resolved"].get<bool>());
  EXPECT_LT(json["left_shared"]["mean_db"].get<double>(), 0.05);
  for (const auto& st : json["locate"]["strikes"]) EXPECT_GT(st["gap_before_held_out"].get<double>(), 0.0);
}

TEST(AuditCli, BadInputGetsOneLineAndExitTwo) {
  TempDir d;
  ASSERT_EQ(run_cli("audit-generate --seed 8 -o " + d.file("a"), d).exit_code, 0);
  ASSERT_EQ(run_cli("audit-generate --seed 9 -o " + d.file("b"), d).exit_code, 0);
  // A 48 kHz recording among 44.1 kHz ones.
  Audio odd = read_audio(d.file("a/strike2.wav"));
  odd.sample_rate_hz = 48000;
  write_wav(d.file("odd.wav"), odd, SampleFormat::float32);
  Audio quiet = odd;
  quiet.sample_rate_hz = 44100;
  std::fill(quiet.samples.begin(), quiet.samples.end(), 0.0f);
  write_wav(d.file("silent.wav"), quiet, SampleFormat::float32);
  ASSERT_EQ(run_cli("audit-generate --seed 9 --strikes 1 -o " + d.file("one"), d).exit_code, 0);
  // A model of another object (b's strike 1, rendered as a parameter set from its own audit report).
  ASSERT_EQ(run_cli("audit --measured" + strikes(d, "b", 5) + " --report " + d.file("rb"), d).exit_code, 0);
  const struct {
    std::string args, expect;
  } cases[] = {
      {"audit --measured" + strikes(d, "a", 2) + " " + d.file("odd.wav"), "sample rate 48000 Hz differs"},
      {"audit --measured" + strikes(d, "a", 2) + " " + d.file("silent.wav"), "silent"},
      {"audit --measured " + d.file("one/strike1.wav"), "at least 2 strikes"},
      {"audit --measured" + strikes(d, "a", 5) + " --model " + d.file("rb/model.yaml"), "do not match the recordings"},
      {"audit-generate --seed 1 --effects reverb -o " + d.file("x"), "unknown effect 'reverb'"},
  };
  for (const auto& c : cases) {
    const RunResult r = run_cli(c.args, d);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_EQ(count_lines(r.err), 1u) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
}  // namespace ms::test
