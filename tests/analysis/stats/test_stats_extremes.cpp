// Statistics at the edges: data near the double range computed exactly (against R on the same data
// divided by 1e300, tests/data/extremes/make_golden.R), undefined statistics refused instead of NaN/inf.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/stats/rm_anova.hpp"
#include "analysis/stats/rm_data.hpp"
#include "analysis/stats/t_test.hpp"
#include "synthesis/tidy_csv.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/extremes/";

void expect_rel(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-9 * std::abs(expected)) << what;
}

}  // namespace

TEST(StatsExtremes, TTestsOn1e300AgreeWithR) {
  const TidyCsv data = TidyCsv::read(kDir + "ttest_1e300.csv");
  std::vector<double> x, y;
  for (std::size_t r = 0; r < data.rows(); ++r)
    (data.cell(r, data.column("group")) == "a" ? x : y).push_back(data.number(r, data.column("v")));
  const TidyCsv golden = TidyCsv::read(kDir + "ttest_1e300_golden.csv");
  for (std::size_t r = 0; r < golden.rows(); ++r) {
    const std::string m = golden.cell(r, 0);
    const TTest t = m == "welch" ? welch_t_test(x, y) : m == "student" ? student_t_test(x, y) : paired_t_test(x, y);
    expect_rel(t.t, golden.number(r, golden.column("t")), m + " t");
    expect_rel(t.df, golden.number(r, golden.column("df")), m + " df");
    expect_rel(t.p, golden.number(r, golden.column("p")), m + " p");
    expect_rel(t.mean_diff, golden.number(r, golden.column("mean_diff")), m + " mean_diff");
    expect_rel(t.ci_low, golden.number(r, golden.column("ci_low")), m + " ci_low");
    expect_rel(t.ci_high, golden.number(r, golden.column("ci_high")), m + " ci_high");
  }
}

TEST(StatsExtremes, ConstantDataHaveNoTStatistic) {
  // Equal differences (R: "data are essentially constant"), and two constant groups.
  EXPECT_THROW(paired_t_test({1, 2, 3}, {0, 1, 2}), std::domain_error);
  EXPECT_THROW(paired_t_test({1, 2, 3}, {1, 2, 3}), std::domain_error);
  EXPECT_THROW(welch_t_test({2, 2, 2}, {1, 1}), std::domain_error);
  EXPECT_THROW(student_t_test({2, 2, 2}, {1, 1}), std::domain_error);
  // One constant group is fine for Welch: df = n - 1 of the other.
  EXPECT_NEAR(welch_t_test({2, 2, 2}, {1, 2, 3}).df, 2.0, 1e-12);
}

namespace {

RmData one_factor(const std::string& csv) {
  std::vector<std::string> notices;
  return rm_data_from_table(TidyCsv::parse(csv, "a.csv"), RmColumns{"v", "s", {"A"}, {}}, notices);
}

}  // namespace

TEST(StatsExtremes, AnovaWithoutErrorVarianceIsRefused) {
  // Every subject shows the same +1 effect: SS_err is 0 up to rounding.
  const RmData exact = one_factor("s,A,v\n1,x,1\n1,y,2\n2,x,2\n2,y,3\n3,x,3\n3,y,4\n");
  try {
    rm_anova(exact);
    FAIL() << "F from a zero error term";
  } catch (const std::domain_error& e) {
    EXPECT_NE(std::string(e.what()).find("effect A: the error sum of squares is 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(rm_anova(one_factor("s,A,v\n1,x,1\n1,y,1\n2,x,1\n2,y,1\n3,x,1\n3,y,1\n")), std::domain_error);
}

TEST(StatsExtremes, AnovaScaleInvariantUpTo1e300) {
  const std::string body = "1,x,1\n1,y,2\n2,x,2\n2,y,3.5\n3,x,3\n3,y,4\n4,x,1\n4,y,3\n";
  const RmAnova small = rm_anova(one_factor("s,A,v\n" + body));
  // The same data times 2^500 (about 3e150): F, p and ges identical, SS exactly 2^1000 times larger
  // (squares of the values themselves would overflow were they not scaled first).
  std::string scaled = "s,A,v\n";
  const double k = std::ldexp(1.0, 500);
  for (const char* row : {"1,x,1", "1,y,2", "2,x,2", "2,y,3.5", "3,x,3", "3,y,4", "4,x,1", "4,y,3"}) {
    std::string r = row;
    const auto c = r.rfind(',');
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", std::stod(r.substr(c + 1)) * k);
    scaled += r.substr(0, c + 1) + buf + "\n";
  }
  const RmAnova big = rm_anova(one_factor(scaled));
  ASSERT_EQ(big.effects.size(), 1u);
  EXPECT_DOUBLE_EQ(big.effects[0].F, small.effects[0].F);
  EXPECT_DOUBLE_EQ(big.effects[0].p, small.effects[0].p);
  EXPECT_DOUBLE_EQ(big.effects[0].ges, small.effects[0].ges);
  EXPECT_DOUBLE_EQ(big.effects[0].ss, small.effects[0].ss * k * k);
  // Values near 1e300: F is fine but the SS (~1e600) are not doubles: refused, not printed as inf.
  std::string huge = "s,A,v\n";
  for (const char* row : {"1,x,1e300", "1,y,2e300", "2,x,2e300", "2,y,3.5e300", "3,x,3e300", "3,y,4e300"})
    huge += std::string(row) + "\n";
  EXPECT_THROW(rm_anova(one_factor(huge)), std::domain_error);
}
