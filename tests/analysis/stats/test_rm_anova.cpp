// Repeated-measures ANOVA against afex::aov_ez / car golden tables (tests/data/anova/make_golden.R),
// against the textbook marginal-means computation, and the design structure of the 2019 study.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>

#include "analysis/stats/rm_anova.hpp"
#include "analysis/stats/rm_data.hpp"
#include "analysis/stats/t_test.hpp"
#include "synthesis/tidy_csv.hpp"
#include "support/naive_anova.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/anova/";

// |a - b| <= 1e-6 |b| (with a floor for values that are zero in exact arithmetic).
void expect_rel(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-6 * std::abs(expected) + 1e-12) << what;
}

struct GoldenCase {
  std::string name;
  std::vector<std::string> within;
  std::vector<std::string> between;
};

class AfexGolden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(AfexGolden, EveryNumberMatches) {
  const GoldenCase& c = GetParam();
  const TidyCsv data = TidyCsv::read(kDir + c.name + ".csv");
  const TidyCsv golden = TidyCsv::read(kDir + c.name + "_golden.csv");
  std::vector<std::string> notices;
  const RmData d = rm_data_from_table(
      data, RmColumns{"rating", "subject", c.within, c.between},
      notices);
  const RmAnova a = rm_anova(d);
  ASSERT_EQ(a.effects.size(), golden.rows());
  auto g = [&](std::size_t r, const char* col) { return golden.number(r, golden.column(col)); };
  auto is_na = [&](std::size_t r, const char* col) { return golden.cell(r, golden.column(col)) == "NA"; };
  for (std::size_t r = 0; r < golden.rows(); ++r) {
    const RmEffect& e = a.effects[r];
    const std::string tag = c.name + " " + e.name;
    EXPECT_EQ(e.name, golden.cell(r, golden.column("effect"))) << c.name;
    expect_rel(e.df1, g(r, "df1"), tag + " df1");
    expect_rel(e.df2, g(r, "df2"), tag + " df2");
    expect_rel(e.F, g(r, "F"), tag + " F");
    expect_rel(e.p, g(r, "p"), tag + " p");
    expect_rel(e.p_gg, g(r, "p_gg"), tag + " p_gg");
    expect_rel(e.p_hf, g(r, "p_hf"), tag + " p_hf");
    expect_rel(e.ges, g(r, "ges"), tag + " ges");
    expect_rel(e.pes, g(r, "pes"), tag + " pes");
    // afex's corrected numerator df = df1 * eps (HF capped at 1).
    if (e.eps_gg) expect_rel(e.df1 * *e.eps_gg, g(r, "df1_gg"), tag + " df1_gg");
    if (e.eps_hf) expect_rel(e.df1 * std::min(1.0, *e.eps_hf), g(r, "df1_hf"), tag + " df1_hf");
    if (!is_na(r, "eps_gg")) {
      ASSERT_TRUE(e.eps_gg && e.eps_hf) << tag;
      expect_rel(*e.eps_gg, g(r, "eps_gg"), tag + " eps_gg");
      expect_rel(*e.eps_hf, g(r, "eps_hf"), tag + " eps_hf");
    } else if (e.within) {
      // car lists no correction for 1-df effects: both epsilons are exactly 1 there.
      ASSERT_TRUE(e.eps_gg && e.eps_hf) << tag;
      EXPECT_NEAR(*e.eps_gg, 1.0, 1e-12) << tag;
      EXPECT_NEAR(*e.eps_hf, 1.0, 1e-12) << tag;
    } else {
      EXPECT_FALSE(e.eps_gg.has_value()) << tag;
    }
    if (!is_na(r, "mauchly_w")) {
      ASSERT_TRUE(e.mauchly_w && e.mauchly_p) << tag;
      expect_rel(*e.mauchly_w, g(r, "mauchly_w"), tag + " mauchly_w");
      expect_rel(*e.mauchly_p, g(r, "mauchly_p"), tag + " mauchly_p");
    } else {
      EXPECT_FALSE(e.mauchly_w.has_value()) << tag;
    }
  }
  // The repeated-observation set is averaged per cell, with a notice; the others are not.
  EXPECT_EQ(notices.size(), c.name == "w2rep" ? 1u : 0u);
}

INSTANTIATE_TEST_SUITE_P(RmAnova, AfexGolden,
                         ::testing::Values(GoldenCase{"w1", {"A"}, {}}, GoldenCase{"w2", {"A", "B"}, {}},
                                           GoldenCase{"w3", {"A", "B", "C"}, {}},
                                           GoldenCase{"w2b", {"A", "B"}, {"group"}},
                                           GoldenCase{"w3b", {"A", "B", "C"}, {"group"}},
                                           GoldenCase{"w3b_bal", {"A", "B", "C"}, {"group"}},
                                           GoldenCase{"w2rep", {"A", "B"}, {}},
                                           GoldenCase{"w2bb", {"A", "B"}, {"group", "site"}}),
                         [](const ::testing::TestParamInfo<GoldenCase>& p) { return p.param.name; });

// Within factor order and row order do not change any effect (only names permute).
TEST(RmAnova, FactorOrderIsImmaterial) {
  const TidyCsv data = TidyCsv::read(kDir + "w3.csv");
  std::vector<std::string> notices;
  const RmAnova abc = rm_anova(rm_data_from_table(data, RmColumns{"rating", "subject", {"A", "B", "C"}, {}}, notices));
  const RmAnova cab = rm_anova(rm_data_from_table(data, RmColumns{"rating", "subject", {"C", "A", "B"}, {}}, notices));
  std::map<std::string, const RmEffect*> by_name;
  // Canonical name: factors sorted.
  auto canon = [](std::string n) {
    std::vector<std::string> parts;
    std::size_t s = 0;
    for (std::size_t i = 0; i <= n.size(); ++i)
      if (i == n.size() || n[i] == ':') {
        parts.push_back(n.substr(s, i - s));
        s = i + 1;
      }
    std::sort(parts.begin(), parts.end());
    std::string out;
    for (auto& p : parts) out += (out.empty() ? "" : ":") + p;
    return out;
  };
  for (const auto& e : abc.effects) by_name[canon(e.name)] = &e;
  ASSERT_EQ(cab.effects.size(), 7u);
  for (const auto& e : cab.effects) {
    const RmEffect* o = by_name.at(canon(e.name));
    EXPECT_NEAR(e.F, o->F, 1e-9 * o->F) << e.name;
    EXPECT_NEAR(*e.eps_gg, *o->eps_gg, 1e-12) << e.name;
    if (e.mauchly_w) {
      EXPECT_NEAR(*e.mauchly_w, *o->mauchly_w, 1e-12) << e.name;
    }
  }
}

// Normalised Helmert contrasts: orthonormal and orthogonal to the constant.
TEST(RmAnova, ContrastsAreOrthonormal) {
  for (std::size_t l : {2u, 3u, 5u, 8u}) {
    const Eigen::MatrixXd k = orthonormal_contrasts(l);
    EXPECT_NEAR((k.transpose() * k - Eigen::MatrixXd::Identity(Eigen::Index(l - 1), Eigen::Index(l - 1))).norm(), 0, 1e-14);
    EXPECT_NEAR((Eigen::RowVectorXd::Ones(Eigen::Index(l)) * k).norm(), 0, 1e-14);
  }
}

// Synthetic long data of the 2019 design: 24 listeners x 5 materials x 2 shapes x 4 datasets.
std::string study_2019_csv(std::vector<test::LongRow>* rows) {
  std::mt19937_64 rng(2019);
  std::normal_distribution<double> noise(0.0, 1.0);
  const char* materials[] = {"wood", "metal", "plastic", "glass", "porcelain"};
  const char* shapes[] = {"disc", "rod"};
  const char* sets[] = {"recorded", "handtuned", "ren", "emg"};
  std::string csv = "listener,material,shape,dataset,pitch\n";
  for (int s = 0; s < 24; ++s) {
    const double listener = noise(rng);
    for (int m = 0; m < 5; ++m)
      for (int h = 0; h < 2; ++h)
        for (int d = 0; d < 4; ++d) {
          // Ordinal 7-point ratings as in the study: material and shape effects plus noise, rounded.
          const double y = std::clamp(std::round(4 + 0.6 * (m - 2) + 0.5 * h + 0.2 * d + 0.5 * listener + noise(rng)), 1.0, 7.0);
          csv += "L" + std::to_string(s) + "," + materials[m] + "," + shapes[h] + "," + sets[d] + "," +
                 std::to_string(int(y)) + "\n";
          if (rows) rows->push_back(test::LongRow{s, {m, h, d}, y});
        }
  }
  return csv;
}

TEST(RmAnova, Study2019TableStructure) {
  std::vector<test::LongRow> rows;
  const TidyCsv data = TidyCsv::parse(study_2019_csv(&rows), "study2019.csv");
  std::vector<std::string> notices;
  const RmAnova a =
      rm_anova(rm_data_from_table(data, RmColumns{"pitch", "listener", {"material", "shape", "dataset"}, {}}, notices));
  // Table 1.2 of Sterling et al. (2019): the degrees of freedom of every row.
  const std::map<std::string, std::pair<double, double>> published = {
      {"material", {4, 92}},          {"shape", {1, 23}},          {"dataset", {3, 69}},
      {"material:shape", {4, 92}},    {"material:dataset", {12, 276}}, {"shape:dataset", {3, 69}},
      {"material:shape:dataset", {12, 276}}};
  ASSERT_EQ(a.effects.size(), published.size());
  EXPECT_EQ(a.n_subjects, 24u);
  for (const auto& e : a.effects) {
    const auto& df = published.at(e.name);
    EXPECT_EQ(e.df1, df.first) << e.name;
    EXPECT_EQ(e.df2, df.second) << e.name;
  }
  // And the same F as the textbook marginal-means computation on the long data.
  const auto naive = test::naive_within_anova(rows, {5, 2, 4}, 24);
  ASSERT_EQ(naive.size(), a.effects.size());
  for (std::size_t i = 0; i < naive.size(); ++i) {
    EXPECT_NEAR(a.effects[i].ss, naive[i].ss, 1e-9 * naive[i].ss) << a.effects[i].name;
    EXPECT_NEAR(a.effects[i].ss_error, naive[i].ss_error, 1e-9 * naive[i].ss_error) << a.effects[i].name;
    EXPECT_NEAR(a.effects[i].F, naive[i].F, 1e-9 * naive[i].F) << a.effects[i].name;
  }
}

// The p column of the 2019 table follows from its F and df: our F distribution reproduces the
// published p values to the digits printed (Pitch material:dataset .0012, Tonality
// material:shape:dataset .0035, Tonality material:dataset 0.107).
TEST(RmAnova, PublishedPValuesFromF) {
  EXPECT_NEAR(f_upper_p(2.814, 12, 276), 0.0012, 0.00005);
  EXPECT_NEAR(f_upper_p(2.53, 12, 276), 0.0035, 0.00005);
  EXPECT_NEAR(f_upper_p(1.548, 12, 276), 0.107, 0.0005);
}

TEST(TTest, MatchesRTTest) {
  const TidyCsv golden = TidyCsv::read(kDir + "ttest_golden.csv");
  auto g = [&](std::size_t r, const char* col) { return golden.number(r, golden.column(col)); };
  // Paired: mean per subject and condition, subjects matched.
  const TidyCsv paired = TidyCsv::read(kDir + "ttest_paired.csv");
  std::map<std::string, std::array<double, 4>> acc;  // sum before, n before, sum after, n after
  for (std::size_t r = 0; r < paired.rows(); ++r) {
    auto& a = acc[paired.cell(r, paired.column("subject"))];
    const int k = paired.cell(r, paired.column("condition")) == "before" ? 0 : 2;
    a[std::size_t(k)] += paired.number(r, paired.column("rating"));
    a[std::size_t(k) + 1] += 1;
  }
  std::vector<double> before, after;
  for (const auto& [s, a] : acc) {
    before.push_back(a[0] / a[1]);
    after.push_back(a[2] / a[3]);
  }
  const TTest tp = paired_t_test(before, after);
  const TidyCsv indep = TidyCsv::read(kDir + "ttest_independent.csv");
  std::vector<double> rec, syn;
  for (std::size_t r = 0; r < indep.rows(); ++r)
    (indep.cell(r, 0) == "recorded" ? rec : syn).push_back(indep.number(r, 1));
  const TTest tw = welch_t_test(rec, syn), ts = student_t_test(rec, syn);
  const TTest* tests[] = {&tp, &tw, &ts};
  for (std::size_t r = 0; r < 3; ++r) {
    const std::string tag = golden.cell(r, 0);
    expect_rel(tests[r]->t, g(r, "t"), tag + " t");
    expect_rel(tests[r]->df, g(r, "df"), tag + " df");
    expect_rel(tests[r]->p, g(r, "p"), tag + " p");
    expect_rel(tests[r]->ci_low, g(r, "ci_low"), tag + " ci_low");
    expect_rel(tests[r]->ci_high, g(r, "ci_high"), tag + " ci_high");
  }
}

// A one-way design with two levels: the RM-ANOVA F is the square of the paired t.
TEST(RmAnova, TwoLevelFIsPairedTSquared) {
  const TidyCsv data = TidyCsv::read(kDir + "ttest_paired.csv");
  std::vector<std::string> notices;
  const RmAnova a = rm_anova(rm_data_from_table(data, RmColumns{"rating", "subject", {"condition"}, {}}, notices));
  ASSERT_EQ(a.effects.size(), 1u);
  EXPECT_EQ(notices.size(), 1u);  // two observations per cell averaged
  const TidyCsv golden = TidyCsv::read(kDir + "ttest_golden.csv");
  const double t = golden.number(0, golden.column("t"));
  expect_rel(a.effects[0].F, t * t, "F = t^2");
  expect_rel(a.effects[0].p, golden.number(0, golden.column("p")), "p");
}

}  // namespace
