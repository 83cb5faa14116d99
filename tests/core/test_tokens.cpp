// The `tokens` block (the adaptive token procedure of van den Doel et al. 2002, Exp. 2) end to end in
// core: the protocol keys and their located refusals, the answer codec, each comparison committed and a
// series resumed mid-way, the autopilot, and tokens.csv read by `stats tokens` as exported.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>

#include "core_fixtures.hpp"
#include "studyapp/core/answers.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {
namespace {

// A six-mode set (amplitudes falling with frequency) pruned in naive order: the token of K modes keeps
// the K loudest. Blocks start on line 10.
std::string write_study(const test::TempDir& dir, const std::string& blocks) {
  dir.write("sets/six.yaml",
            "sample_rate: 44100\nduration_s: 0.4\nmodes:\n"
            "  - {freq_hz: 300.0, decay_per_s: 8.0, amp: 0.6}\n  - {freq_hz: 710.0, decay_per_s: 9.0, amp: 0.4}\n"
            "  - {freq_hz: 1330.0, decay_per_s: 11.0, amp: 0.25}\n  - {freq_hz: 2150.0, decay_per_s: 14.0, amp: 0.12}\n"
            "  - {freq_hz: 3400.0, decay_per_s: 18.0, amp: 0.05}\n  - {freq_hz: 5230.0, decay_per_s: 25.0, amp: 0.02}\n"
            "excitation: {type: impulse}\nlevel: {normalize: none}\n");
  return dir.write("study.yaml",
                   "study: tok\ntitle: Tokens\nsample_rate: 44100\nseed: 7\nstimuli:\n"
                   "  six: {paramset: sets/six.yaml, prune: {method: naive}}\n"
                   "  flat: {paramset: sets/six.yaml}\n"
                   "  rec: {derive: six, lowpass_hz: 3500}\n"
                   "blocks:\n" + blocks);
}

const std::string kBlock = "  - {type: tokens, id: tok, stimulus: six, from: 6, to: 1, repeats: 2}\n";

TEST(TokensAnswer, RoundTripsAndRefusesSeriesTheRuleDoesNotGive) {
  const TokensAnswer a{6, 1, {false, true, false, false, true}};
  const nlohmann::json j = a;
  EXPECT_EQ(j, nlohmann::json::parse(R"({"from":6,"to":1,"responses":["same","different","same","same","different"],
                                         "distinguished":[6,4,1]})"));
  const Answer stored = read_stored_answer("tokens", j);
  const auto& back = std::get<TokensAnswer>(stored);
  EXPECT_EQ(back.from, 6);
  EXPECT_EQ(back.to, 1);
  EXPECT_EQ(back.different, a.different);
  const auto refused = [](const char* text) {
    try {
      read_stored_answer("tokens", nlohmann::json::parse(text));
    } catch (const AnswerError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refused(R"({"from":3,"to":1,"responses":["same"],"distinguished":[3]})").find("2 responses from 3 to 1, got 1"),
            std::string::npos);
  EXPECT_NE(refused(R"({"from":3,"to":1,"responses":["same","different"],"distinguished":[3,2]})")
                .find("must be the references the responses lead to, [3,1]"), std::string::npos);
  EXPECT_NE(refused(R"({"from":1,"to":1,"responses":[],"distinguished":[1]})").find("from more modes to fewer"),
            std::string::npos);
  EXPECT_NE(refused(R"({"from":3,"to":1,"responses":["same","maybe"],"distinguished":[3]})").find("same, different"),
            std::string::npos);
  EXPECT_NE(refused(R"({"from":3,"to":1,"responses":["same","same"]})").find("expected {"), std::string::npos);
}

std::string only_problem(const test::TempDir& dir, const std::string& block) {
  const auto problems = check_protocol_file(write_study(dir, block), {}).problems;
  return problems.size() == 1 ? problems[0] : "problems: " + std::to_string(problems.size());
}

TEST(TokensProtocol, BadKeysAreRefusedWithTheirPlace) {
  test::TempDir dir;
  const std::string file = dir.file("study.yaml");
  std::string p = only_problem(dir, "  - {type: tokens, id: tok, stimulus: six, from: 6, to: 6}\n");
  EXPECT_NE(p.find(file + ":10:57: blocks[0].to"), std::string::npos) << p;
  EXPECT_NE(p.find("must lie below from"), std::string::npos) << p;
  p = only_problem(dir, "  - {type: tokens, id: tok, stimulus: six, from: 1}\n");
  EXPECT_NE(p.find(file + ":10:50: blocks[0].from"), std::string::npos) << p;
  p = only_problem(dir, "  - {type: tokens, id: tok, stimulus: six, from: 7}\n");  // more than the set has
  EXPECT_NE(p.find(file + ":10:50: block 'tok': 'from' is 7 but stimulus 'six' keeps only 6 modes"), std::string::npos) << p;
  p = only_problem(dir, "  - {type: tokens, id: tok, stimulus: flat, from: 6}\n");
  EXPECT_NE(p.find(file + ":10:39: block 'tok': stimulus 'flat' has no 'prune:'"), std::string::npos) << p;
  p = only_problem(dir, "  - {type: tokens, id: tok, stimulus: rec, from: 6}\n");
  EXPECT_NE(p.find("not a parameter set"), std::string::npos) << p;
  p = only_problem(dir, "  - {type: tokens, id: tok, stimulus: six, from: 6, feedback: true}\n");  // no right answer
  EXPECT_NE(p.find("feedback"), std::string::npos) << p;
  p = only_problem(dir, "  - {type: tokens, id: tok, stimulus: six}\n");
  EXPECT_NE(p.find("a 'tokens' block needs 'from'"), std::string::npos) << p;
  EXPECT_TRUE(check_protocol_file(write_study(dir, kBlock), {}).problems.empty());
}

Session open(const std::string& path, const std::string& db, std::int64_t now_ms, const Protocol& protocol) {
  StimulusCache cache(protocol, "");
  return Session(protocol, testing::file_text(path), "P05", db, cache.hashes(), now_ms);
}

TEST(TokensSession, ComparisonsAreCommittedAndASeriesResumesMidWay) {
  test::TempDir dir;
  const std::string path = write_study(dir, kBlock);
  const Protocol protocol = load_protocol(path);
  {
    Session s = open(path, dir.file("r.sqlite"), 1000, protocol);
    ASSERT_EQ(s.total(), 2u);  // one trial per series
    EXPECT_EQ(s.current().stimuli, std::vector<std::string>{"six"});
    EXPECT_THROW(s.answer("different", 1.0, 1, 1000), std::invalid_argument);  // a series is not one answer
    EXPECT_EQ(s.tokens().reference(), 6);
    EXPECT_EQ(s.tokens().comparison(), 5);
    EXPECT_TRUE(s.tokens_step(false, 300.0, 2000));  // 5 heard as 6: discarded
    EXPECT_TRUE(s.tokens_step(true, 300.0, 2001));   // 4 differs: the new reference
  }
  Session s = open(path, dir.file("r.sqlite"), 3000, protocol);
  ASSERT_TRUE(s.resumed());
  ASSERT_EQ(s.current().type, BlockType::tokens);
  EXPECT_EQ(s.tokens().different().size(), 2u);  // rebuilt from the committed steps
  EXPECT_EQ(s.tokens().reference(), 4);
  EXPECT_EQ(s.tokens().comparison(), 3);
  EXPECT_TRUE(s.tokens_step(false, 300.0, 4000));   // 3
  EXPECT_TRUE(s.tokens_step(false, 300.0, 4001));   // 2
  EXPECT_FALSE(s.tokens_step(true, 300.0, 4002));   // 1: the last token; the trial is answered
  EXPECT_EQ(s.store().answered_trials(s.id()).size(), 1u);
  EXPECT_EQ(s.tokens().reference(), 6);  // the next series starts at the top
  const Trial& second = s.current();
  const auto r = s.store().response(s.id(), {int(second.block), second.index == 0 ? 1 : 0});
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(nlohmann::json::parse(r->value_json),
            nlohmann::json::parse(R"({"from":6,"to":1,"responses":["same","different","same","same","different"],
                                      "distinguished":[6,4,1]})"));
  EXPECT_EQ(r->plays, 5);
  EXPECT_DOUBLE_EQ(r->rt_ms, 1500.0);  // the series' steps, those before the resume included
  // Each comparison is a step event naming both tokens.
  const auto events = s.store().events(s.id(), {int(second.block), second.index == 0 ? 1 : 0});
  std::vector<std::pair<int, int>> pairs;
  for (const auto& e : events)
    if (e.kind == EventKind::step) {
      const auto d = nlohmann::json::parse(e.detail_json);
      pairs.emplace_back(d["reference"].get<int>(), d["comparison"].get<int>());
    }
  EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{6, 5}, {6, 4}, {4, 3}, {4, 2}, {4, 1}}));
  while (s.tokens_step(true, 300.0, 5000)) {
  }
  EXPECT_TRUE(s.finished());
}

TEST(TokensExport, AutopilotSeriesReadByStatsTokensAsExported) {
  test::TempDir dir;
  AutopilotOptions o;
  o.protocol_path = write_study(dir, kBlock);
  o.db_path = dir.file("study.sqlite");
  o.cache_dir = dir.file("cache");
  ASSERT_TRUE(testing::run_participants_and_export(o, 3, "T", 21, dir.file("out")));
  const TidyCsv t = TidyCsv::read(dir.file("out/tokens.csv"));
  ASSERT_EQ(t.rows(), 30u);  // 3 participants x 2 series x 5 comparisons
  std::map<std::string, int> stored;  // series -> distinguished, as exported
  std::map<std::string, int> different;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string series = t.cell(r, t.column("participant")) + "/" + t.cell(r, t.column("trial"));
    stored[series] = std::stoi(t.cell(r, t.column("distinguished")));
    different[series] += t.cell(r, t.column("different")) == "1";
    EXPECT_EQ(t.cell(r, t.column("tokens")), "6");
    EXPECT_EQ(t.cell(r, t.column("stimulus")), "six");
  }
  ASSERT_EQ(stored.size(), 6u);
  for (const auto& [series, n] : stored) EXPECT_EQ(n, 1 + different[series]) << series;
  const auto run = test::run_cli("stats tokens " + dir.file("out/tokens.csv") + " --json", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["conditions"].size(), 1u);
  EXPECT_EQ(j["conditions"][0]["tokens_min"], 6);
  ASSERT_EQ(j["participants"].size(), 3u);
  for (const auto& p : j["participants"]) {
    const std::string who = p["participant"].get<std::string>();
    const double mean = (stored[who + "/0"] + stored[who + "/1"]) / 2.0;
    EXPECT_DOUBLE_EQ(p["cells"]["tok"]["distinguished"].get<double>(), mean) << who;
    EXPECT_EQ(p["cells"]["tok"]["series"], 2) << who;
  }
}

}  // namespace
}  // namespace ms
