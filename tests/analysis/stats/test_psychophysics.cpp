// A/B family: exact binomial test vs R's binom.test, d' for 2AFC / ABX / same-different vs the
// Macmillan & Creelman formulas evaluated in R (tests/data/psychophysics/make_golden.R), closed
// forms, and staircase thresholds (hand track; Levitt's 70.7 % point of a 1-up/2-down rule).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "analysis/stats/binomial_test.hpp"
#include "analysis/stats/signal_detection.hpp"
#include "analysis/stats/staircase.hpp"
#include "synthesis/tidy_csv.hpp"

using namespace ms;

namespace {
const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/psychophysics/";
void expect_rel(double actual, double expected, double rel, const std::string& what) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected) + 1e-15) << what;
}
}  // namespace

TEST(BinomialTest, MatchesRBinomTest) {
  const TidyCsv g = TidyCsv::read(kDir + "binom_golden.csv");
  ASSERT_GE(g.rows(), 9u);
  for (std::size_t r = 0; r < g.rows(); ++r) {
    const std::string alt = g.cell(r, g.column("alternative"));
    const Alternative a = alt == "greater" ? Alternative::greater : alt == "less" ? Alternative::less : Alternative::two_sided;
    const BinomialTest t = binomial_test(unsigned(g.number(r, 0)), unsigned(g.number(r, 1)), g.number(r, 2), a);
    const std::string tag = g.cell(r, 0) + "/" + g.cell(r, 1) + " " + alt;
    expect_rel(t.p, g.number(r, g.column("p")), 1e-9, tag + " p");
    expect_rel(t.ci_low, g.number(r, g.column("ci_low")), 1e-9, tag + " ci_low");
    expect_rel(t.ci_high, g.number(r, g.column("ci_high")), 1e-9, tag + " ci_high");
  }
}

// Closed forms: 7/10 two-sided at 1/2 is 2 P(X >= 7) = 2 * 176/1024; 20/20 greater is 2^-20.
TEST(BinomialTest, ClosedForms) {
  EXPECT_NEAR(binomial_test(7, 10).p, 2.0 * 176.0 / 1024.0, 1e-15);
  EXPECT_NEAR(binomial_test(20, 20, 0.5, Alternative::greater).p, std::ldexp(1.0, -20), 1e-20);
  EXPECT_NEAR(binomial_test(5, 10).p, 1.0, 0);
}

TEST(SignalDetection, DprimeMatchesR) {
  const TidyCsv g = TidyCsv::read(kDir + "dprime_golden.csv");
  for (std::size_t r = 0; r < g.rows(); ++r) {
    const double pc = g.number(r, 0);
    expect_rel(dprime_2afc(pc), g.number(r, g.column("dprime_2afc")), 1e-12, "2afc " + g.cell(r, 0));
    expect_rel(dprime_abx(pc), g.number(r, g.column("dprime_abx")), 1e-9, "abx " + g.cell(r, 0));
    // Round trips through the forward models.
    EXPECT_NEAR(pc_2afc(dprime_2afc(pc)), pc, 1e-14);
    EXPECT_NEAR(pc_abx(dprime_abx(pc)), pc, 1e-13);
  }
  const TidyCsv s = TidyCsv::read(kDir + "same_different_golden.csv");
  for (std::size_t r = 0; r < s.rows(); ++r) {
    const SameDifferent sd = dprime_same_different(s.number(r, 0), s.number(r, 1));
    expect_rel(sd.criterion_k, s.number(r, s.column("k")), 1e-12, "k " + s.cell(r, 0));
    expect_rel(sd.dprime, s.number(r, s.column("dprime")), 1e-9, "d' " + s.cell(r, 0));
    EXPECT_NEAR(hit_rate_same_different(sd.dprime, sd.criterion_k), s.number(r, 0), 1e-13);
  }
}

// Values from Macmillan & Creelman one can check by hand: 2AFC p_c = .76 is d' = 1 (sqrt2 z(.76)
// = 0.9989); yes-no H = .69, F = .31 is d' = 2 z(.69) = 0.9917 (z(.69) = 0.49585); chance is d' = 0 in every design;
// at d' = 0 the same-different model has H = F.
TEST(SignalDetection, ClosedForms) {
  EXPECT_NEAR(dprime_2afc(0.76), 0.99886, 1e-5);
  EXPECT_NEAR(dprime_yes_no(0.69, 0.31), 2 * normal_quantile(0.69), 1e-14);
  EXPECT_NEAR(dprime_yes_no(0.69, 0.31), 0.99170, 1e-5);
  EXPECT_EQ(dprime_2afc(0.5), 0.0);
  EXPECT_EQ(dprime_abx(0.5), 0.0);
  EXPECT_EQ(dprime_abx(0.4), 0.0);  // below chance
  EXPECT_NEAR(pc_abx(0.0), 0.5, 1e-16);
  EXPECT_NEAR(hit_rate_same_different(0.0, 1.3), 2 * normal_cdf(-1.3 / std::sqrt(2.0)), 1e-15);
  EXPECT_EQ(dprime_same_different(0.3, 0.3).dprime, 0.0);
  // 1/(2N) correction of perfect scores.
  EXPECT_DOUBLE_EQ(corrected_rate(20, 20), 1 - 1.0 / 40);
  EXPECT_DOUBLE_EQ(corrected_rate(0, 20), 1.0 / 40);
  EXPECT_DOUBLE_EQ(corrected_rate(7, 20), 0.35);
}

StaircaseOptions last(std::size_t k, bool log_scale = false) {
  StaircaseOptions o;
  o.last_k = k;
  o.log_scale = log_scale;
  return o;
}

TEST(Staircase, HandTrack) {
  // Down, down, up (reversal at 6), up, down (reversal at 8), flat, down, up (reversal at 5).
  const std::vector<double> levels = {10, 8, 6, 7, 8, 7, 7, 5, 6};
  const auto t = staircase_threshold(levels, std::nullopt, last(2));
  ASSERT_EQ(t.reversal_levels, (std::vector<double>{6, 8, 5}));
  EXPECT_EQ(t.reversal_trials, (std::vector<std::size_t>{2, 4, 7}));
  EXPECT_EQ(t.used, 2u);
  EXPECT_DOUBLE_EQ(*t.threshold, 6.5);
  EXPECT_NEAR(*t.sd, std::sqrt(4.5), 1e-12);
  EXPECT_NEAR(*staircase_threshold(levels, std::nullopt, last(3, true)).threshold, std::cbrt(6.0 * 8 * 5), 1e-12);
  EXPECT_FALSE(staircase_threshold({1, 2, 3}, std::nullopt, last(4)).threshold.has_value());
  // Default: at most four reversals are all averaged.
  EXPECT_DOUBLE_EQ(*staircase_threshold(levels, std::nullopt).threshold, (6.0 + 8 + 5) / 3);
}

TEST(Staircase, NextLevelCountsAReversalAtTheLastTrial) {
  // 10 9 8 9 10 9 8 9 10 9 8 (then up to 9): reversals at 8, 10, 8, 10, 8 - the last seen only with
  // the level after the last answer.
  const std::vector<double> levels = {10, 9, 8, 9, 10, 9, 8, 9, 10, 9, 8};
  const auto without = staircase_threshold(levels, std::nullopt);
  EXPECT_EQ(without.reversal_levels, (std::vector<double>{8, 10, 8, 10}));
  EXPECT_DOUBLE_EQ(*without.threshold, 9.0);  // four: all
  const auto with = staircase_threshold(levels, 9.0);
  EXPECT_EQ(with.reversal_levels, (std::vector<double>{8, 10, 8, 10, 8}));
  EXPECT_EQ(with.reversal_trials.back(), 10u);
  EXPECT_EQ(with.used, 3u);  // five: the first two skipped
  EXPECT_DOUBLE_EQ(*with.threshold, (8.0 + 10 + 8) / 3);
  // Levels far from zero: the standard deviation does not cancel.
  const auto far = staircase_threshold({1e9 + 1, 1e9, 1e9 + 1, 1e9}, 1e9 + 1, last(3));
  EXPECT_NEAR(*far.sd, std::sqrt(1.0 / 3.0), 1e-6);
}

// Levitt (1971): a 1-up/2-down rule converges on the 70.7 % point of the psychometric function.
TEST(Staircase, OneUpTwoDownConvergesTo707Percent) {
  std::mt19937_64 rng(1971);
  std::uniform_real_distribution<double> u(0, 1);
  const double mid = 10, slope = 1.5;  // 2AFC: p = 0.5 + 0.5 logistic((L - mid)/slope)
  auto p_correct = [&](double level) { return 0.5 + 0.5 / (1 + std::exp(-(level - mid) / slope)); };
  const double q = (std::sqrt(0.5) - 0.5) / 0.5;  // p = sqrt(1/2)
  const double target = mid + slope * std::log(q / (1 - q));
  double sum = 0;
  const int tracks = 400;
  for (int k = 0; k < tracks; ++k) {
    std::vector<double> levels;
    double level = 16;
    int run = 0;
    for (int trial = 0; trial < 120; ++trial) {
      levels.push_back(level);
      if (u(rng) < p_correct(level)) {
        if (++run == 2) {
          level -= 0.5;
          run = 0;
        }
      } else {
        level += 0.5;
        run = 0;
      }
    }
    sum += *staircase_threshold(levels, level, last(8)).threshold;
  }
  EXPECT_NEAR(sum / tracks, target, 0.25) << "70.7% point " << target;
}
