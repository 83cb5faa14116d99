// The `limits` block (descending method of limits, van den Doel et al. 2002 Exp. 1) end to end in core:
// the series rule, the protocol keys and their located refusals, the answer codec, steps committed and
// a series resumed mid-way, the autopilot, and limits.csv read by `stats limits` as exported.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>

#include "core_fixtures.hpp"
#include "studyapp/core/answers.hpp"
#include "studyapp/core/descending_series.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {
namespace {

using testing::good_answer;
using testing::SmallStudy;

const std::string kLimits =
    "  - {type: limits, id: lim, stimulus: low, reference: high, parameter: amp_scale, start: 1.0,\n"
    "     step: -0.1, floor: 0.5, repeats: 2}\n";

TEST(DescendingSeries, FallsByTheStepAndEndsAtTheFirstDifferent) {
  DescendingSeries s(20.0, -1.0, std::nullopt);
  for (int i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(s.level(), 20.0 - i);
    s.record(false);
    EXPECT_FALSE(s.finished());
  }
  s.record(true);  // at 16
  EXPECT_TRUE(s.finished());
  EXPECT_EQ(s.levels(), (std::vector<double>{20, 19, 18, 17, 16}));
  ASSERT_TRUE(s.threshold().has_value());
  EXPECT_DOUBLE_EQ(*s.threshold(), 17.0);  // the smallest level at which no change was heard
}

TEST(DescendingSeries, DifferentAtTheStartHasNoThresholdAndTheFloorEndsASeries) {
  DescendingSeries first(20.0, -1.0, std::nullopt);
  first.record(true);
  EXPECT_TRUE(first.finished());
  EXPECT_FALSE(first.threshold().has_value());  // it lies above the start
  // Levels are start + k step: a 0.1 step reaches the floor 0.5 exactly, on the sixth trial.
  DescendingSeries floored(1.0, -0.1, 0.5);
  int trials = 0;
  while (!floored.finished()) floored.record(false), ++trials;
  EXPECT_EQ(trials, 6);
  EXPECT_NEAR(floored.levels().back(), 0.5, 1e-12);
  EXPECT_NEAR(*floored.threshold(), 0.5, 1e-12);  // censored: the last level
  DescendingSeries endless(0.0, -1.0, std::nullopt);
  while (!endless.finished()) endless.record(false);
  EXPECT_EQ(endless.levels().size(), DescendingSeries::kMaxSteps);
}

TEST(LimitsAnswer, RoundTripsAndRefusesBadSeries) {
  const LimitsAnswer a{"prune.threshold_db", {20, 19, 18}, {false, false, true}, 19.0};
  const nlohmann::json j = a;
  EXPECT_EQ(j["responses"], nlohmann::json::parse(R"(["same","same","different"])"));
  const Answer back = read_stored_answer("limits", j);
  const auto& b = std::get<LimitsAnswer>(back);
  EXPECT_EQ(b.levels, a.levels);
  EXPECT_EQ(b.different, a.different);
  EXPECT_EQ(*b.threshold, 19.0);
  const auto refused = [](const char* text) {
    try {
      read_stored_answer("limits", nlohmann::json::parse(text));
    } catch (const AnswerError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refused(R"({"parameter":"k","levels":[20,21],"responses":["same","different"],"threshold":20})")
                .find("must fall"), std::string::npos);
  EXPECT_NE(refused(R"({"parameter":"k","levels":[20,19],"responses":["same"],"threshold":20})")
                .find("one response per level"), std::string::npos);
  EXPECT_NE(refused(R"({"parameter":"k","levels":[20,19],"responses":["different","same"],"threshold":null})")
                .find("first \"different\""), std::string::npos);
  EXPECT_NE(refused(R"({"parameter":"k","levels":[20],"responses":["maybe"],"threshold":null})")
                .find("same, different"), std::string::npos);
}

// One problem, located at the key.
std::string only_problem(const test::TempDir& dir, const std::string& block) {
  const std::string path = testing::write_small_study(dir, block);
  const auto problems = check_protocol_file(path, {}).problems;
  return problems.size() == 1 ? problems[0] : "problems: " + std::to_string(problems.size());
}

TEST(LimitsProtocol, BadKeysAreRefusedWithTheirPlace) {
  test::TempDir dir;
  const std::string file = dir.file("study.yaml");
  const std::string head = "  - {type: limits, id: lim, stimulus: low, parameter: amp_scale, start: 1.0, ";
  std::string p = only_problem(dir, head + "step: 0.1}\n");
  EXPECT_NE(p.find(file + ":14:84: blocks[3].step"), std::string::npos) << p;  // at the value
  EXPECT_NE(p.find("negative step"), std::string::npos) << p;
  p = only_problem(dir, head + "step: -0.1, floor: 2}\n");
  EXPECT_NE(p.find("must lie below start"), std::string::npos) << p;
  p = only_problem(dir, head + "step: -0.1, feedback: true}\n");  // no right answer to feed back
  EXPECT_NE(p.find("feedback"), std::string::npos) << p;
  p = only_problem(dir, "  - {type: limits, id: lim, stimulus: low, start: 1.0, step: -1}\n");
  EXPECT_NE(p.find("parameter"), std::string::npos) << p;
  p = only_problem(dir, "  - {type: limits, id: lim, stimulus: lp, parameter: amp_scale, start: 1, step: -1}\n");
  EXPECT_NE(p.find("not a parameter set"), std::string::npos) << p;
  const std::string good = testing::write_small_study(dir, kLimits);
  EXPECT_TRUE(check_protocol_file(good, {}).problems.empty());
}

TEST(LimitsSession, StepsAreCommittedAndASeriesResumesMidWay) {
  test::TempDir dir;
  SmallStudy study(dir, kLimits);
  {
    Session s = study.open("P05", dir.file("r.sqlite"), 1000);
    ASSERT_EQ(s.total(), 8u);  // the small study's 6 + one trial per series
    while (s.current().type != BlockType::limits) s.answer(good_answer(s), 1.0, 1, 1000);
    EXPECT_EQ(s.current().stimuli, (std::vector<std::string>{"low", "high"}));
    EXPECT_THROW(s.answer("different", 1.0, 1, 1000), std::invalid_argument);  // a series is not one answer
    EXPECT_TRUE(s.limits_step(false, 300.0, 2000));
    EXPECT_TRUE(s.limits_step(false, 300.0, 2001));
  }
  Session s = study.open("P05", dir.file("r.sqlite"), 3000);
  ASSERT_TRUE(s.resumed());
  ASSERT_EQ(s.current().type, BlockType::limits);
  EXPECT_EQ(s.limits().levels().size(), 2u);  // rebuilt from the committed steps
  EXPECT_NEAR(s.limits().level(), 0.8, 1e-12);
  EXPECT_TRUE(s.limits_step(false, 300.0, 4000));  // 0.8
  EXPECT_FALSE(s.limits_step(true, 300.0, 4001));  // 0.7: the series ends, the trial is answered
  const std::size_t first = s.store().answered_trials(s.id()).size();
  EXPECT_EQ(first, 7u);
  const Trial& second = s.current();
  ASSERT_EQ(second.type, BlockType::limits);
  EXPECT_EQ(s.limits().levels().size(), 0u);  // a new series starts at the start
  EXPECT_DOUBLE_EQ(s.limits().level(), 1.0);
  const int block = int(second.block);
  const int other = second.index == 0 ? 1 : 0;
  const auto r = s.store().response(s.id(), {block, other});
  ASSERT_TRUE(r.has_value());
  const auto v = nlohmann::json::parse(r->value_json);
  EXPECT_EQ(v["parameter"], "amp_scale");
  ASSERT_EQ(v["levels"].size(), 4u);
  EXPECT_EQ(v["responses"].back(), "different");
  EXPECT_NEAR(v["threshold"].get<double>(), 0.8, 1e-12);
  EXPECT_EQ(r->plays, 4);
  EXPECT_DOUBLE_EQ(r->rt_ms, 1200.0);  // the series' steps, the one before the resume included
  while (s.limits_step(false, 300.0, 5000)) {
  }
  EXPECT_TRUE(s.finished());  // the second series ran to its floor
}

TEST(LimitsExport, AutopilotSeriesReadByStatsLimitsAsExported) {
  test::TempDir dir;
  const std::string path = testing::write_small_study(dir, kLimits);
  AutopilotOptions o;
  o.protocol_path = path;
  o.db_path = dir.file("study.sqlite");
  o.cache_dir = dir.file("cache");
  ASSERT_TRUE(testing::run_participants_and_export(o, 3, "L", 11, dir.file("out")));
  const TidyCsv t = TidyCsv::read(dir.file("out/limits.csv"));
  std::map<std::string, std::string> stored;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string series = t.cell(r, t.column("participant")) + "/" + t.cell(r, t.column("block")) + "/" +
                               t.cell(r, t.column("trial"));
    stored[series] = t.cell(r, t.column("threshold"));
    EXPECT_EQ(t.cell(r, t.column("stimulus")), "low");
    EXPECT_EQ(t.cell(r, t.column("reference")), "high");
  }
  ASSERT_EQ(stored.size(), 6u);  // 3 participants x 2 series
  const auto run = test::run_cli("stats limits " + dir.file("out/limits.csv") +
                                     " --level level --response response --track participant,block,trial --json",
                                 dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["tracks"].size(), 6u);
  for (const auto& track : j["tracks"]) {
    const std::string name = track["track"].get<std::string>();
    ASSERT_TRUE(stored.count(name)) << name;
    if (stored[name] == "NA") EXPECT_TRUE(track["threshold"].is_null()) << name;
    else EXPECT_NEAR(track["threshold"].get<double>(), std::stod(stored[name]), 1e-12) << name;
  }
}

}  // namespace
}  // namespace ms
