// The BS.1116 summary against SciPy (tests/data/bs1116/make_golden.py): difference grades per condition
// over assessors, and each assessor's one-sided t-test; webMUSHRA's table read as the export's.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/stats/bs1116.hpp"
#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/tidy_csv.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/bs1116/";

void expect_rel(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-9 * std::abs(expected) + 1e-12) << what;
}

}  // namespace

TEST(Bs1116Summary, DifferenceGradesAndScreeningMatchSciPy) {
  const Bs1116Result res = bs1116_analyse(bs1116_from_table(TidyCsv::read(kDir + "grades.csv")));
  const TidyCsv summary = TidyCsv::read(kDir + "summary_golden.csv");
  ASSERT_EQ(res.conditions.size(), summary.rows());
  EXPECT_EQ(res.averaged, 8u * 3u);  // two repeats per assessor and condition
  for (std::size_t r = 0; r < summary.rows(); ++r) {
    const MushraStat& c = res.conditions[r];
    EXPECT_EQ(c.condition, summary.cell(r, 0));
    EXPECT_EQ(c.n, 8u);
    expect_rel(c.mean, summary.number(r, 2), c.condition + " mean");
    expect_rel(c.sd, summary.number(r, 3), c.condition + " sd");
    ASSERT_TRUE(c.ci_low && c.ci_high);
    expect_rel(*c.ci_low, summary.number(r, 4), c.condition + " ci_low");
    expect_rel(*c.ci_high, summary.number(r, 5), c.condition + " ci_high");
    EXPECT_FALSE(c.ci_past_scale);
  }
  const TidyCsv screen = TidyCsv::read(kDir + "screening_golden.csv");
  ASSERT_EQ(res.assessors.size(), screen.rows());
  for (std::size_t r = 0; r < screen.rows(); ++r) {
    const Bs1116Assessor& a = res.assessors[r];
    EXPECT_EQ(a.subject, screen.cell(r, 0));
    EXPECT_EQ(double(a.trials), screen.number(r, 1));
    EXPECT_EQ(double(a.positive), screen.number(r, 2));
    expect_rel(a.mean, screen.number(r, 3), a.subject + " mean");
    ASSERT_TRUE(a.t && a.p_less);
    expect_rel(*a.t, screen.number(r, 4), a.subject + " t");
    expect_rel(*a.p_less, screen.number(r, 5), a.subject + " p");
  }
  // The planted assessor who cannot tell the hidden reference is the one with a large p.
  EXPECT_GT(*res.assessors.back().p_less, 0.1);
}

TEST(Bs1116Summary, WebMushrasTableGivesTheSameGrades) {
  test::TempDir dir;
  const std::string wm = dir.write("bs1116.csv",
                                   "session_test_id,session_uuid,trial_id,rating_reference,rating_non_reference,"
                                   "rating_reference_score,rating_non_reference_score,rating_time,choice_comment\n"
                                   "t,s1,bs,reference,C1,5,3.5,900,\n"
                                   "t,s1,bs,reference,C2,4.8,4.9,900,\n"
                                   "t,s2,bs,reference,C1,4.9,3.1,900,\n");
  const std::vector<Bs1116Grade> g = bs1116_from_table(TidyCsv::read(wm));
  ASSERT_EQ(g.size(), 3u);
  EXPECT_EQ(g[0].subject, "s1");
  EXPECT_EQ(g[0].condition, "C1");
  EXPECT_DOUBLE_EQ(g[0].diffgrade, -1.5);
  EXPECT_NEAR(g[1].diffgrade, 0.1, 1e-12);
  const Bs1116Result res = bs1116_analyse(g);
  EXPECT_EQ(res.assessors[0].positive, 1u);
  EXPECT_FALSE(res.conditions[1].ci_low);  // one assessor graded C2: no interval
}

TEST(Bs1116Summary, BadTablesAreOneLocatedLine) {
  test::TempDir dir;
  const auto error = [&](const std::string& text) {
    try {
      bs1116_from_table(TidyCsv::read(dir.write("b.csv", text)));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string outside = error("participant,condition,diffgrade\nL1,c,-4.5\n");
  EXPECT_NE(outside.find("b.csv:2:6: column 'diffgrade': difference grade"), std::string::npos) << outside;
  EXPECT_NE(error("participant,condition,diffgrade\n,c,-1\n").find("column 'participant': empty"), std::string::npos);
  EXPECT_NE(error("participant,diffgrade\nL1,-1\n").find("missing column 'condition'"), std::string::npos);
  EXPECT_NE(error("participant,condition,diffgrade\n").find("no data rows"), std::string::npos);
}
