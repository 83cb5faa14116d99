// A magnitude block's bounded scale (the 2002 study's 1-10, 1 = identical): its keys and located
// refusals, the answer check, the typed entry, the simulated listener and the exported columns.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core_fixtures.hpp"
#include "studyapp/core/answers.hpp"
#include "studyapp/core/magnitude_input.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {
namespace {

const std::string kScaled =
    "  - {type: magnitude, id: mag, modulus: [low, high], pairs: all_with_identical, stimuli: [low, high, lowq],\n"
    "     scale: {min: 1, max: 10}}\n";

std::vector<std::string> problems_of(const test::TempDir& dir, const std::string& block) {
  return check_protocol_file(testing::write_small_study(dir, block), {}).problems;
}

TEST(MagnitudeScale, ParsedWithTheModulusAtItsTopAndBadScalesRefusedWhereWritten) {
  test::TempDir dir;
  const Protocol p = load_protocol(testing::write_small_study(dir, kScaled));
  const auto& m = std::get<MagnitudeBlock>(p.find_block("mag")->body);
  ASSERT_TRUE(m.scale.has_value());
  EXPECT_EQ(m.scale->min, 1.0);
  EXPECT_EQ(m.scale->max, 10.0);
  EXPECT_EQ(m.modulus_value, 10.0);  // the standard pair is the most dissimilar one
  const std::string head = "  - {type: magnitude, id: mag, modulus: [low, high], stimuli: [low, high], ";
  auto p1 = problems_of(dir, head + "scale: {min: 5, max: 5}}\n");
  ASSERT_EQ(p1.size(), 1u);
  EXPECT_NE(p1[0].find("study.yaml:14:97: blocks[3].scale.max"), std::string::npos) << p1[0];  // at max
  EXPECT_NE(p1[0].find("scale.max: must be greater than min"), std::string::npos) << p1[0];
  p1 = problems_of(dir, head + "scale: {min: 1, max: 10}, modulus_value: 100}\n");
  ASSERT_EQ(p1.size(), 1u);
  EXPECT_NE(p1[0].find("modulus_value: must lie on the block's scale (1 to 10)"), std::string::npos) << p1[0];
  p1 = problems_of(dir, head + "scale: {min: 1, top: 10}}\n");
  ASSERT_EQ(p1.size(), 1u);
  EXPECT_NE(p1[0].find("scale"), std::string::npos) << p1[0];
  p1 = problems_of(dir, head + "scale: {min: -1, max: 10}}\n");
  ASSERT_EQ(p1.size(), 1u);
  EXPECT_NE(p1[0].find("must not be negative"), std::string::npos) << p1[0];
}

TEST(MagnitudeScale, AnswersAndTypedEntriesStayOnTheScale) {
  test::TempDir dir;
  const Protocol p = load_protocol(testing::write_small_study(dir, kScaled));
  const Block& b = *p.find_block("mag");
  const Trial t;
  EXPECT_NO_THROW(read_answer(b, t, 1));   // identical
  EXPECT_NO_THROW(read_answer(b, t, 10));  // as dissimilar as the standard pair
  EXPECT_NO_THROW(read_answer(b, t, 5.5));
  EXPECT_THROW(read_answer(b, t, 0), AnswerError);   // below 1, though the block has identical pairs
  EXPECT_THROW(read_answer(b, t, 11), AnswerError);  // an open ratio scale would take it
  const auto& m = std::get<MagnitudeBlock>(b.body);
  EXPECT_EQ(read_magnitude("7,5", m).value, 7.5);
  EXPECT_EQ(read_magnitude("12", m).problem, "Type a number from 1 to 10.");
  EXPECT_EQ(read_magnitude("0", m).problem, "Type a number from 1 to 10.");
  MagnitudeBlock open = m;
  open.scale.reset();
  EXPECT_EQ(read_magnitude("12", open).value, 12.0);  // without a scale, as before
}

TEST(MagnitudeScale, AutopilotAnswersOnTheScaleAndTheExportSaysWhichScale) {
  test::TempDir dir;
  AutopilotOptions o;
  o.protocol_path = testing::write_small_study(dir, kScaled);
  o.db_path = dir.file("study.sqlite");
  o.cache_dir = dir.file("cache");
  ASSERT_TRUE(testing::run_participants_and_export(o, 2, "M", 5, dir.file("out")));
  const TidyCsv t = TidyCsv::read(dir.file("out/magnitude.csv"));
  ASSERT_EQ(t.rows(), 12u);  // 2 x (3 distinct + 3 identical pairs)
  bool identical_at_bottom = false;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double v = t.number(r, t.column("value"));
    EXPECT_GE(v, 1.0);
    EXPECT_LE(v, 10.0);
    EXPECT_EQ(t.cell(r, t.column("scale_min")), "1");
    EXPECT_EQ(t.cell(r, t.column("scale_max")), "10");
    EXPECT_EQ(t.cell(r, t.column("modulus_value")), "10");
    if (t.cell(r, t.column("first")) == t.cell(r, t.column("second")) && v <= 2.0) identical_at_bottom = true;
  }
  EXPECT_TRUE(identical_at_bottom);  // identical sounds are rated near 1, not near 0
}

}  // namespace
}  // namespace ms
