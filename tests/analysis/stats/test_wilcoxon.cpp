// Wilcoxon signed-rank and sign tests against R (tests/data/wilcoxon/make_golden.R: wilcox.test with
// paired = TRUE, binom.test), and sample quantiles against R's quantile(type = 7) / median.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "analysis/stats/quantile.hpp"
#include "synthesis/tidy_csv.hpp"
#include "analysis/stats/wilcoxon.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/wilcoxon/";

Alternative parse_alternative(const std::string& s) {
  return s == "greater" ? Alternative::greater : s == "less" ? Alternative::less : Alternative::two_sided;
}

}  // namespace

TEST(Wilcoxon, MatchesRWilcoxTestOnAllCases) {
  const TidyCsv samples = TidyCsv::read(kDir + "samples.csv");
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> data;
  for (std::size_t r = 0; r < samples.rows(); ++r) {
    auto& xy = data[samples.cell(r, 0)];
    xy.first.push_back(samples.number(r, 2));
    xy.second.push_back(samples.number(r, 3));
  }
  const TidyCsv g = TidyCsv::read(kDir + "golden.csv");
  ASSERT_EQ(g.rows(), 10u);
  int exact_cases = 0, normal_cases = 0;
  for (std::size_t r = 0; r < g.rows(); ++r) {
    const std::string name = g.cell(r, g.column("case"));
    SCOPED_TRACE(name);
    const auto& xy = data.at(name);
    WilcoxonOptions o;
    o.alternative = parse_alternative(g.cell(r, g.column("alternative")));
    const std::string exact = g.cell(r, g.column("exact"));
    o.exact = exact == "exact" ? ExactMode::exact : exact == "normal" ? ExactMode::normal : ExactMode::automatic;
    o.correct = g.number(r, g.column("correct")) != 0;
    const WilcoxonResult w = wilcoxon_signed_rank(xy.first, xy.second, o);
    EXPECT_EQ(w.exact, g.number(r, g.column("exact_used")) != 0);
    EXPECT_DOUBLE_EQ(w.v, g.number(r, g.column("V")));
    const double p = g.number(r, g.column("p"));
    EXPECT_NEAR(w.p, p, 1e-10 * p + 1e-15);
    (w.exact ? exact_cases : normal_cases) += 1;
    const SignTest s = sign_test(xy.first, xy.second, o.alternative);
    EXPECT_EQ(s.positive, int(g.number(r, g.column("sign_positive"))));
    EXPECT_EQ(s.positive + s.negative, int(g.number(r, g.column("sign_n"))));
    const double sp = g.number(r, g.column("sign_p"));
    EXPECT_NEAR(s.p, sp, 1e-10 * sp);
  }
  EXPECT_EQ(exact_cases, 4);
  EXPECT_EQ(normal_cases, 6);
}

// The exact null distribution by hand: n = 3 has 8 equally likely subsets of {1,2,3} with sums
// 0,1,2,3,3,4,5,6.
TEST(Wilcoxon, SignedRankDistributionSmallN) {
  EXPECT_DOUBLE_EQ(signed_rank_cdf(0, 3), 1.0 / 8);
  EXPECT_DOUBLE_EQ(signed_rank_cdf(2, 3), 3.0 / 8);
  EXPECT_DOUBLE_EQ(signed_rank_cdf(3, 3), 5.0 / 8);
  EXPECT_DOUBLE_EQ(signed_rank_cdf(5, 3), 7.0 / 8);
  EXPECT_DOUBLE_EQ(signed_rank_cdf(6, 3), 1.0);
  EXPECT_DOUBLE_EQ(signed_rank_cdf(-1, 3), 0.0);
  // All five differences positive: V = 15, two-sided p = 2/32 (R: 0.0625).
  const WilcoxonResult w = wilcoxon_signed_rank({1, 2, 3, 4, 5}, {0, 0, 0, 0, 0});
  EXPECT_TRUE(w.exact);
  EXPECT_DOUBLE_EQ(w.v, 15);
  EXPECT_DOUBLE_EQ(w.p, 0.0625);
  // One sample against mu: the same differences.
  WilcoxonOptions o;
  o.mu = 1;
  EXPECT_DOUBLE_EQ(wilcoxon_signed_rank({2, 3, 4, 5, 6}, o).p, 0.0625);
  EXPECT_THROW(wilcoxon_signed_rank({1, 2}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(wilcoxon_signed_rank({1, 2}, {1}), std::invalid_argument);
}

// R: quantile(c(3, 1, 4, 1, 5, 9, 2, 6), c(0, .1, .25, .5, .9, 1)) = 1 1 1.75 3.5 6.9 9.
TEST(Quantile, MatchesRType7) {
  const std::vector<double> x{3, 1, 4, 1, 5, 9, 2, 6};
  EXPECT_DOUBLE_EQ(quantile(x, 0), 1);
  EXPECT_DOUBLE_EQ(quantile(x, 0.1), 1);
  EXPECT_DOUBLE_EQ(quantile(x, 0.25), 1.75);
  EXPECT_DOUBLE_EQ(quantile(x, 0.5), 3.5);
  EXPECT_NEAR(quantile(x, 0.9), 6.9, 1e-12);
  EXPECT_DOUBLE_EQ(quantile(x, 1), 9);
  EXPECT_DOUBLE_EQ(median({7}), 7);
  EXPECT_DOUBLE_EQ(median({5, 1, 3}), 3);
  EXPECT_THROW(median({}), std::invalid_argument);
  EXPECT_THROW(quantile(x, 1.5), std::invalid_argument);
}
