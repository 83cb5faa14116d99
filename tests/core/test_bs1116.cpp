// The BS.1116 block (double-blind triple-stimulus with hidden reference): what a protocol must say, one
// trial per condition with the hidden reference as A or B, grades 1.0-5.0, and the tidy table with the
// difference grade.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core_fixtures.hpp"
#include "studyapp/core/answers.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/schedule.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {
namespace {

const std::string kBlock = "  - {type: bs1116, id: bs, reference: low, conditions: [lowq, lp, high], repeats: 4}\n";

std::vector<std::string> problems(const test::TempDir& dir, const std::string& block) {
  return check_protocol_file(testing::write_small_study(dir, block), {}).problems;
}

bool has(const std::vector<std::string>& v, const std::string& part) {
  return std::any_of(v.begin(), v.end(), [&](const std::string& p) { return p.find(part) != std::string::npos; });
}

TEST(Bs1116, ABlockNeedsAReferenceAndConditionsOtherThanIt) {
  test::TempDir dir;
  EXPECT_TRUE(problems(dir, kBlock).empty());
  const auto no_ref = problems(dir, "  - {type: bs1116, id: bs, conditions: [lowq]}\n");
  ASSERT_EQ(no_ref.size(), 1u);
  EXPECT_NE(no_ref[0].find("study.yaml:14:"), std::string::npos) << no_ref[0];
  EXPECT_NE(no_ref[0].find("needs a 'reference'"), std::string::npos) << no_ref[0];
  EXPECT_TRUE(has(problems(dir, "  - {type: bs1116, id: bs, reference: low, conditions: []}\n"), "no conditions"));
  const auto self = problems(dir, "  - {type: bs1116, id: bs, reference: low, conditions: [lowq, low]}\n");
  ASSERT_EQ(self.size(), 1u);
  EXPECT_NE(self[0].find("condition 'low' is the reference"), std::string::npos) << self[0];
  EXPECT_TRUE(has(problems(dir, "  - {type: bs1116, id: bs, reference: low, conditions: [nope]}\n"), "nope"));
  EXPECT_TRUE(has(problems(dir, "  - {type: bs1116, id: bs, reference: low, conditions: [lowq], anchors: auto}\n"),
                  "anchors"));
}

TEST(Bs1116, EachConditionIsATrialWithTheHiddenReferenceAsAOrB) {
  test::TempDir dir;
  const Protocol p = load_protocol(testing::write_small_study(dir, kBlock));
  std::map<std::string, int> count;
  std::set<std::size_t> hidden_at;
  for (const Trial& t : make_schedule(p, "P1").trials) {
    if (t.block_id != "bs") continue;
    EXPECT_EQ(t.reference, "low");
    ASSERT_EQ(t.stimuli.size(), 2u);
    const auto ref = std::find(t.stimuli.begin(), t.stimuli.end(), "low");
    ASSERT_NE(ref, t.stimuli.end());
    hidden_at.insert(std::size_t(ref - t.stimuli.begin()));
    ++count[ref == t.stimuli.begin() ? t.stimuli[1] : t.stimuli[0]];
  }
  EXPECT_EQ(count, (std::map<std::string, int>{{"high", 4}, {"lowq", 4}, {"lp", 4}}));
  EXPECT_EQ(hidden_at, (std::set<std::size_t>{0, 1}));  // 12 draws put it on both sides
  // Without randomisation A is the condition, B the hidden reference.
  const Protocol fixed = load_protocol(testing::write_small_study(
      dir, "  - {type: bs1116, id: bs, reference: low, conditions: [lowq], randomize: false}\n"));
  for (const Trial& t : make_schedule(fixed, "P1").trials)
    if (t.block_id == "bs") EXPECT_EQ(t.stimuli, (std::vector<std::string>{"lowq", "low"}));
}

TEST(Bs1116, GradesAreOneToFiveForBothSounds) {
  test::TempDir dir;
  const Protocol p = load_protocol(testing::write_small_study(dir, kBlock));
  const Block& block = *p.find_block("bs");
  Trial t;
  t.type = BlockType::bs1116;
  t.stimuli = {"lowq", "low"};
  const auto grades = read_answer(block, t, nlohmann::json{{"lowq", 3.4}, {"low", 5.0}});
  EXPECT_EQ(std::get<Bs1116Answer>(grades).grades.at("lowq"), 3.4);
  for (const nlohmann::json& bad : {nlohmann::json{{"lowq", 0.5}, {"low", 5.0}}, nlohmann::json{{"lowq", 5.5}, {"low", 5}},
                                    nlohmann::json{{"lowq", 3.0}}, nlohmann::json{{"lowq", 3.0}, {"high", 5.0}},
                                    nlohmann::json{{"lowq", "3"}, {"low", 5.0}}, nlohmann::json(4.0)})
    EXPECT_THROW(read_answer(block, t, bad), AnswerError) << bad.dump();
  EXPECT_EQ(nlohmann::json(Answer(std::get<Bs1116Answer>(grades))), (nlohmann::json{{"low", 5.0}, {"lowq", 3.4}}));
}

TEST(Bs1116, TheTidyTableNamesTheHiddenReferenceAndTheDifferenceGrade) {
  test::TempDir dir;
  AutopilotOptions o;
  o.protocol_path = testing::write_small_study(dir, kBlock);
  o.db_path = dir.file("r.sqlite");
  o.cache_dir = dir.file("cache");
  ASSERT_TRUE(testing::run_participants_and_export(o, 3, "P", 21, dir.file("out")));
  const TidyCsv bs = TidyCsv::read(dir.file("out/bs1116.csv"));
  ASSERT_EQ(bs.rows(), 3u * 12u);
  double hidden_sum = 0, high_sum = 0;
  int high_n = 0;
  for (std::size_t r = 0; r < bs.rows(); ++r) {
    EXPECT_EQ(bs.cell(r, bs.column("reference")), "low");
    const std::string side = bs.cell(r, bs.column("hidden_reference"));
    EXPECT_TRUE(side == "A" || side == "B") << side;
    const double c = bs.number(r, bs.column("condition_grade")), h = bs.number(r, bs.column("reference_grade"));
    EXPECT_NEAR(bs.number(r, bs.column("diffgrade")), c - h, 1e-9);
    EXPECT_TRUE(c >= 1.0 && c <= 5.0 && h >= 1.0 && h <= 5.0);
    hidden_sum += h;
    if (bs.cell(r, bs.column("condition")) == "high") high_sum += c, ++high_n;
  }
  // The simulated listener hears the hidden reference as the reference and another pitch as different.
  EXPECT_GT(hidden_sum / double(bs.rows()), 4.5);
  EXPECT_LT(high_sum / high_n, 3.0);
}

}  // namespace
}  // namespace ms
