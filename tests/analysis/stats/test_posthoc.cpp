// Post-hoc pairwise t-tests and p adjustment against R's pairwise.t.test and p.adjust on the same
// data (tests/data/posthoc/make_golden.R writes data.csv and golden.csv).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/stats/posthoc.hpp"
#include "analysis/stats/rm_data.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {
namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/posthoc/";

RmData design() {
  std::vector<std::string> notices;
  return rm_data_from_table(TidyCsv::read(kDir + "data.csv"),
                            RmColumns{"score", "subject", {"method", "material"}, {"group"}}, notices);
}

// The comparison of the two levels, whichever order the design lists them in; the sign of the
// difference is turned to R's a - b.
struct Found {
  const PairwiseComparison* pair = nullptr;
  double sign = 1;
};
Found find(const Posthoc& h, const std::string& a, const std::string& b) {
  for (const auto& c : h.pairs) {
    if (c.level_a == a && c.level_b == b) return {&c, 1};
    if (c.level_a == b && c.level_b == a) return {&c, -1};
  }
  return {};
}

TEST(Posthoc, MatchesPairwiseTTestOfR) {
  const RmData data = design();
  const TidyCsv golden = TidyCsv::read(kDir + "golden.csv");
  const auto col = [&](const char* name) { return golden.column(name); };
  int checked = 0;
  for (std::size_t r = 0; r < golden.rows(); ++r) {
    const std::string factor = golden.cell(r, col("factor"));
    const Posthoc h = pairwise_t_tests(data, factor, p_adjust_from_name(golden.cell(r, col("adjust"))));
    EXPECT_EQ(h.within, factor == "method");
    ASSERT_EQ(h.pairs.size(), 3u);
    const Found f = find(h, golden.cell(r, col("a")), golden.cell(r, col("b")));
    ASSERT_NE(f.pair, nullptr) << golden.cell(r, col("a")) << " vs " << golden.cell(r, col("b"));
    EXPECT_NEAR(f.pair->p, golden.number(r, col("p")), 1e-10 * golden.number(r, col("p")) + 1e-14);
    EXPECT_NEAR(f.pair->p_adjusted, golden.number(r, col("p_adjusted")),
                1e-10 * golden.number(r, col("p_adjusted")) + 1e-14);
    EXPECT_NEAR(f.sign * f.pair->mean_diff, golden.number(r, col("mean_diff")), 1e-9);
    if (factor == "method") {
      EXPECT_NEAR(f.sign * f.pair->t, golden.number(r, col("t")), 1e-9);
      EXPECT_DOUBLE_EQ(f.pair->df, 8.0);  // nine subjects, paired
    } else {
      EXPECT_DOUBLE_EQ(f.pair->df, 6.0);  // nine subjects in three groups, SD pooled over all
    }
    ++checked;
  }
  EXPECT_EQ(checked, 18);
}

TEST(Posthoc, HolmIsMonotoneAndNeverAboveBonferroni) {
  const std::vector<double> p{0.01, 0.04, 0.03, 0.005, 0.5};
  const auto holm = p_adjust(p, PAdjust::holm);
  const auto bonf = p_adjust(p, PAdjust::bonferroni);
  // By hand: sorted 0.005, 0.01, 0.03, 0.04, 0.5 times 5, 4, 3, 2, 1 = 0.025, 0.04, 0.09, 0.08 -> 0.09
  // (running maximum), 0.5.
  EXPECT_DOUBLE_EQ(holm[3], 0.025);
  EXPECT_DOUBLE_EQ(holm[0], 0.04);
  EXPECT_NEAR(holm[2], 0.09, 1e-15);
  EXPECT_NEAR(holm[1], 0.09, 1e-15);
  EXPECT_DOUBLE_EQ(holm[4], 0.5);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_LE(holm[i], bonf[i]);
    EXPECT_GE(holm[i], p[i]);
  }
  EXPECT_DOUBLE_EQ(bonf[4], 1.0);  // capped
  EXPECT_EQ(p_adjust(p, PAdjust::none), p);
}

TEST(Posthoc, RefusesWhatItCannotCompute) {
  const RmData data = design();
  EXPECT_THROW(pairwise_t_tests(data, "colour", PAdjust::holm), std::invalid_argument);
  EXPECT_THROW(p_adjust_from_name("tukey"), std::invalid_argument);
  RmData flat = data;
  flat.cell_mean.setConstant(3.0);
  EXPECT_THROW(pairwise_t_tests(flat, "method", PAdjust::holm), std::domain_error);
  EXPECT_THROW(pairwise_t_tests(flat, "group", PAdjust::holm), std::domain_error);
}

}  // namespace
}  // namespace ms
