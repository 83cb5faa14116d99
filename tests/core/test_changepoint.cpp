// The `changepoint` block (Skandalou & Ireland 2017, Exp. 3: mark where the material changed along a
// fixed-order sweep) end to end in core: the protocol keys and their located refusals, one trial per
// sweep with its sounds in the written order, the answer codec and its check against the trial, and
// changepoint.csv read by `stats changepoint` as exported.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>

#include "core_fixtures.hpp"
#include "studyapp/core/answers.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {
namespace {

using testing::good_answer;
using testing::SmallStudy;

// Two sweeps over the small study's three parameter sets, twice each: 4 trials.
const std::string kBlock =
    "  - {type: changepoint, id: cp, parameter: Q, values: [1000, 1600, 2200],\n"
    "     sweeps: [[low, lowq, high], [high, lowq, low]], repeats: 2}\n";

TEST(ChangepointAnswer, RoundTripsAndRefusesMarksThatAreNoPositions) {
  const ChangepointAnswer a{{1, 3}};
  const nlohmann::json j = a;
  EXPECT_EQ(j, nlohmann::json::parse(R"({"marks":[1,3]})"));
  EXPECT_EQ(std::get<ChangepointAnswer>(read_stored_answer("changepoint", j)).marks, a.marks);
  EXPECT_TRUE(std::get<ChangepointAnswer>(read_stored_answer("changepoint", nlohmann::json::parse(R"({"marks":[]})")))
                  .marks.empty());  // no change heard is an answer too
  const auto refused = [](const char* text) {
    try {
      read_stored_answer("changepoint", nlohmann::json::parse(text));
    } catch (const AnswerError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refused(R"({"marks":[0]})").find("the first sound cannot be marked"), std::string::npos);
  EXPECT_NE(refused(R"({"marks":[2,1]})").find("rise and are distinct"), std::string::npos);
  EXPECT_NE(refused(R"({"marks":[2,2]})").find("rise and are distinct"), std::string::npos);
  EXPECT_NE(refused(R"({"marks":[-1]})").find("a sound's position"), std::string::npos);
  EXPECT_NE(refused(R"({"marks":[1.5]})").find("a sound's position"), std::string::npos);
  EXPECT_NE(refused(R"([1,2])").find("expected {\"marks\""), std::string::npos);
}

std::string only_problem(const test::TempDir& dir, const std::string& block) {
  const auto problems = check_protocol_file(testing::write_small_study(dir, block), {}).problems;
  return problems.size() == 1 ? problems[0] : "problems: " + std::to_string(problems.size());
}

TEST(ChangepointProtocol, BadSweepsAreRefusedWithTheirPlace) {
  test::TempDir dir;
  const std::string file = dir.file("study.yaml");
  const std::string head = "  - {type: changepoint, id: cp, parameter: Q, ";
  std::string p = only_problem(dir, head + "values: [1, 2], sweeps: [[low, high]]}\n");
  EXPECT_NE(p.find(file + ":14:55: blocks[3].values"), std::string::npos) << p;
  EXPECT_NE(p.find("at least 3 sounds"), std::string::npos) << p;
  p = only_problem(dir, head + "values: [1, 3, 2], sweeps: [[low, lowq, high]]}\n");
  EXPECT_NE(p.find(file + ":14:62: blocks[3].values[2]"), std::string::npos) << p;  // at the value that turns back
  EXPECT_NE(p.find("must rise all the way"), std::string::npos) << p;
  p = only_problem(dir, head + "values: [3, 2, 2], sweeps: [[low, lowq, high]]}\n");
  EXPECT_NE(p.find("must fall all the way"), std::string::npos) << p;
  p = only_problem(dir, head + "values: [1, 2, 3], sweeps: [[low, lowq]]}\n");
  EXPECT_NE(p.find("blocks[3].sweeps[0]"), std::string::npos) << p;
  EXPECT_NE(p.find("has 2 sounds but 'values' has 3"), std::string::npos) << p;
  p = only_problem(dir, head + "values: [1, 2, 3], sweeps: [[low, lowq, low]]}\n");
  EXPECT_NE(p.find("blocks[3].sweeps[0][2]"), std::string::npos) << p;
  EXPECT_NE(p.find("plays 'low' twice"), std::string::npos) << p;
  p = only_problem(dir, head + "values: [1, 2, 3], sweeps: [[low, lowq, hihg]]}\n");
  EXPECT_NE(p.find("unknown stimulus 'hihg' (did you mean 'high'?)"), std::string::npos) << p;
  p = only_problem(dir, "  - {type: changepoint, id: cp, values: [1, 2, 3], sweeps: [[low, lowq, high]]}\n");
  EXPECT_NE(p.find("a 'changepoint' block needs 'parameter'"), std::string::npos) << p;
  p = only_problem(dir, head + "values: [1, 2, 3], sweeps: []}\n");
  EXPECT_NE(p.find("expected a list of sweeps"), std::string::npos) << p;
  p = only_problem(dir, head + "values: [1, 2, 3], sweeps: [[low, lowq, high]], feedback: true}\n");
  EXPECT_NE(p.find("feedback"), std::string::npos) << p;
  EXPECT_TRUE(check_protocol_file(testing::write_small_study(dir, kBlock), {}).problems.empty());
}

TEST(ChangepointSchedule, OneTrialPerSweepInTheWrittenOrder) {
  test::TempDir dir;
  const Protocol p = load_protocol(testing::write_small_study(dir, kBlock));
  std::set<std::vector<std::string>> orders;
  for (const char* who : {"P1", "P2", "P3", "P4", "P5", "P6"}) {
    std::vector<std::string> sweeps_in_order;
    for (const Trial& t : make_schedule(p, who).trials) {
      if (t.type != BlockType::changepoint) continue;
      const bool first = t.stimuli == std::vector<std::string>{"low", "lowq", "high"};
      const bool second = t.stimuli == std::vector<std::string>{"high", "lowq", "low"};
      EXPECT_TRUE(first || second) << who;  // never reordered within the sweep
      sweeps_in_order.push_back(first ? "a" : "b");
    }
    EXPECT_EQ(sweeps_in_order.size(), 4u);
    orders.insert(sweeps_in_order);
  }
  EXPECT_GT(orders.size(), 1u);  // the trials themselves are shuffled per participant
}

TEST(ChangepointSession, MarksAreCheckedAgainstTheSweepBeforeTheyAreStored) {
  test::TempDir dir;
  SmallStudy study(dir, kBlock);
  Session s = study.open("P05", dir.file("r.sqlite"), 1000);
  while (s.current().type != BlockType::changepoint) s.answer(good_answer(s), 1.0, 1, 1000);
  const std::size_t before = s.answered();
  EXPECT_THROW(s.answer(nlohmann::json::parse(R"({"marks":[3]})"), 1.0, 3, 1000), std::invalid_argument);  // past 3 sounds
  EXPECT_EQ(s.answered(), before);  // nothing stored
  const Trial sweep = s.current();
  s.answer(ChangepointAnswer{{2}}, 4000.0, 3, 2000);
  const auto r = s.store().response(s.id(), {int(sweep.block), int(sweep.index)});
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(nlohmann::json::parse(r->value_json), nlohmann::json::parse(R"({"marks":[2]})"));
}

TEST(ChangepointExport, OneRowPerSoundReadByStatsChangepointAsExported) {
  test::TempDir dir;
  const std::string path = testing::write_small_study(dir, kBlock);
  AutopilotOptions o;
  o.protocol_path = path;
  o.db_path = dir.file("study.sqlite");
  o.cache_dir = dir.file("cache");
  ASSERT_TRUE(testing::run_participants_and_export(o, 3, "C", 5, dir.file("out")));
  const TidyCsv t = TidyCsv::read(dir.file("out/changepoint.csv"));
  ASSERT_EQ(t.rows(), 36u);  // 3 participants x 4 sweeps x 3 sounds
  std::map<double, int> marks;  // value -> marks, counted from the rows
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string stimulus = t.cell(r, t.column("stimulus"));
    const std::size_t position = std::stoul(t.cell(r, t.column("position")));
    const double value = t.number(r, t.column("value"));
    EXPECT_EQ(t.cell(r, t.column("parameter")), "Q");
    EXPECT_DOUBLE_EQ(value, 1000.0 + 600.0 * double(position));  // the block's value at the position
    if (position == 0) EXPECT_EQ(t.cell(r, t.column("marked")), "0");
    marks[value] += t.cell(r, t.column("marked")) == "1";
  }
  const auto run = test::run_cli("stats changepoint " + dir.file("out/changepoint.csv") + " --json", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["groups"].size(), 1u);
  EXPECT_EQ(j["groups"][0]["sweeps"], 12);
  for (const auto& c : j["groups"][0]["counts"]) EXPECT_EQ(c["marks"], marks[c["value"].get<double>()]) << c.dump();
}

}  // namespace
}  // namespace ms
