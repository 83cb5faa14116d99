// Confusion-matrix statistics against scikit-learn / SciPy (tests/data/confusion/make_golden.py),
// Newcombe's published intervals, and the 2013 recorded-vs-synthesised material tables.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "analysis/stats/confusion.hpp"
#include "synthesis/tidy_csv.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/confusion/";

nlohmann::json golden() {
  std::ifstream in(kDir + "golden.json");
  return nlohmann::json::parse(in);
}

void expect_rel(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-9 * std::abs(expected) + 1e-12) << what;
}

Confusion read_confusion(const std::string& file, const std::vector<std::string>& labels) {
  const TidyCsv t = TidyCsv::read(kDir + file);
  std::vector<std::string> truth, response;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    truth.push_back(t.cell(r, t.column("material")));
    response.push_back(t.cell(r, t.column("answer")));
  }
  return confusion_from_pairs(labels, truth, response);
}

Eigen::MatrixXd read_percent_table(const std::string& file) {
  const TidyCsv t = TidyCsv::read(kDir + file);
  Eigen::MatrixXd m(Eigen::Index(t.rows()), Eigen::Index(t.header().size() - 1));
  for (std::size_t r = 0; r < t.rows(); ++r)
    for (std::size_t c = 1; c < t.header().size(); ++c) m(Eigen::Index(r), Eigen::Index(c - 1)) = t.number(r, c);
  return m;
}

}  // namespace

TEST(Confusion, MatchesSklearnAndScipy) {
  const auto g = golden();
  const auto labels = g["labels"].get<std::vector<std::string>>();
  for (const char* which : {"recorded", "synthesised"}) {
    const auto& e = g[which];
    const Confusion c = read_confusion(std::string("responses_") + which + ".csv", labels);
    const Eigen::MatrixXd pct = row_percent(c.counts);
    for (std::size_t i = 0; i < labels.size(); ++i)
      for (std::size_t k = 0; k < labels.size(); ++k) {
        EXPECT_EQ(c.counts(Eigen::Index(i), Eigen::Index(k)), e["counts"][i][k].get<double>()) << which;
        expect_rel(pct(Eigen::Index(i), Eigen::Index(k)), e["row_percent"][i][k].get<double>(), which);
      }
    expect_rel(accuracy(c.counts), e["accuracy"].get<double>(), std::string(which) + " accuracy");
    const auto rec = recall(c.counts);
    for (std::size_t i = 0; i < labels.size(); ++i) expect_rel(rec[i], e["recall"][i].get<double>(), "recall");
    expect_rel(cohen_kappa(c.counts), e["kappa"].get<double>(), std::string(which) + " kappa");
    const ChiSquareTest chi = chi2_independence(c.counts);
    expect_rel(chi.chi2, e["chi2"].get<double>(), std::string(which) + " chi2");
    EXPECT_EQ(chi.df, e["chi2_df"].get<double>());
    // p is ~1e-85: relative agreement of the tail probability.
    EXPECT_NEAR(chi.p / e["chi2_p"].get<double>(), 1.0, 1e-6) << which;
  }
  const Confusion r = read_confusion("responses_recorded.csv", labels);
  const Confusion s = read_confusion("responses_synthesised.csv", labels);
  const auto& cmp = g["recorded_vs_synthesised"];
  expect_rel(frobenius_distance(row_percent(r.counts), row_percent(s.counts)), cmp["frobenius"].get<double>(),
             "frobenius");
  for (Eigen::Index i = 0; i < 5; ++i) {
    const Interval ci = newcombe_difference(r.counts(i, i), r.counts.row(i).sum(), s.counts(i, i), s.counts.row(i).sum());
    expect_rel(ci.low, cmp["recall_diff_ci"][std::size_t(i)][0].get<double>(), "newcombe low");
    expect_rel(ci.high, cmp["recall_diff_ci"][std::size_t(i)][1].get<double>(), "newcombe high");
  }
}

TEST(Confusion, YatesCorrectionOn2x2AsScipy) {
  const auto y = golden()["yates_2x2"];
  Eigen::MatrixXd m(2, 2);
  m << 12, 3, 5, 10;
  const ChiSquareTest chi = chi2_independence(m);
  EXPECT_TRUE(chi.yates);
  EXPECT_EQ(chi.df, 1);
  expect_rel(chi.chi2, y["chi2"].get<double>(), "chi2");
  expect_rel(chi.p, y["chi2_p"].get<double>(), "p");
}

// Newcombe (1998), Statistics in Medicine 17:873-890, Table II, method 10 (hybrid score interval),
// printed to four decimals.
TEST(Confusion, NewcombePublishedExamples) {
  struct Case {
    double x1, n1, x2, n2, low, high;
  } cases[] = {{56, 70, 48, 80, 0.0524, 0.3339}, {9, 10, 3, 10, 0.1705, 0.8090},  {5, 56, 0, 29, -0.0381, 0.1926},
               {0, 10, 0, 20, -0.1611, 0.2775}, {0, 10, 0, 10, -0.2775, 0.2775}, {10, 10, 0, 20, 0.6791, 1.0000},
               {10, 10, 0, 10, 0.6075, 1.0000}};
  for (const Case& c : cases) {
    const Interval ci = newcombe_difference(c.x1, c.n1, c.x2, c.n2);
    EXPECT_NEAR(ci.low, c.low, 5e-5) << c.x1 << "/" << c.n1 << " - " << c.x2 << "/" << c.n2;
    EXPECT_NEAR(ci.high, c.high, 5e-5) << c.x1 << "/" << c.n1 << " - " << c.x2 << "/" << c.n2;
  }
}

// Closed forms: perfect agreement has kappa 1; chance-level agreement kappa 0; a hand example.
TEST(Confusion, KappaClosedForms) {
  EXPECT_DOUBLE_EQ(cohen_kappa(Eigen::MatrixXd::Identity(4, 4) * 7), 1.0);
  EXPECT_NEAR(cohen_kappa(Eigen::MatrixXd::Constant(3, 3, 5.0)), 0.0, 1e-15);
  Eigen::MatrixXd m(2, 2);
  m << 20, 5, 10, 15;  // po = 0.7, pe = (25*30 + 25*20)/2500 = 0.5
  EXPECT_NEAR(cohen_kappa(m), 0.4, 1e-15);
}

// Ren, Yeh & Lin (US 9,401,684, 2013 study): Tables III (recorded) and IV (synthesised),
// transcribed from the patent text; the Frobenius norm of their difference equals the value the
// committed script computes from the same tables (the patent itself states no norm).
TEST(Confusion, Ren2013RecordedVsSynthesised) {
  const Eigen::MatrixXd rec = read_percent_table("ren2013_table3_recorded_percent.csv");
  const Eigen::MatrixXd syn = read_percent_table("ren2013_table4_synthesised_percent.csv");
  ASSERT_EQ(rec.rows(), 5);
  ASSERT_EQ(syn.cols(), 5);
  // Transcription check: every printed row sums to 100 % within the rounding of five entries.
  for (Eigen::Index i = 0; i < 5; ++i) {
    EXPECT_NEAR(rec.row(i).sum(), 100.0, 0.25) << "Table III row " << i;
    EXPECT_NEAR(syn.row(i).sum(), 100.0, 0.25) << "Table IV row " << i;
  }
  expect_rel(frobenius_distance(rec, syn), golden()["ren2013"]["frobenius_table3_table4"].get<double>(), "frobenius");
  // The text's reading of Table III row 3: metal recognised as metal 66.1 %, as glass 24.2 %.
  EXPECT_DOUBLE_EQ(rec(2, 2), 66.1);
  EXPECT_DOUBLE_EQ(rec(2, 4), 24.2);
}

TEST(Confusion, WaldIntervalAsRPropTest) {
  const TidyCsv g = TidyCsv::read(kDir + "prop_test_golden.csv");
  ASSERT_EQ(g.rows(), 36u);
  for (std::size_t r = 0; r < g.rows(); ++r) {
    const auto num = [&](const char* c) { return g.number(r, g.column(c)); };
    const Interval ci = wald_difference(num("x1"), num("n1"), num("x2"), num("n2"),
                                        g.cell(r, g.column("correct")) == "TRUE", num("conf_level"));
    expect_rel(ci.low, num("low"), "row " + std::to_string(r + 2) + " low");
    expect_rel(ci.high, num("high"), "row " + std::to_string(r + 2) + " high");
  }
}

// Table V of the 2013 study (95 % intervals of recorded - synthesised recognition rates, percent) from
// its Tables III and IV. The tables print percentages only; each row's count of answers is the smallest
// n whose integer counts give every printed percentage (to its 0.1 %) and sum to n.
TEST(Confusion, Ren2013TableVFromTablesIIIAndIV) {
  const Eigen::MatrixXd rec = read_percent_table("ren2013_table3_recorded_percent.csv");
  const Eigen::MatrixXd syn = read_percent_table("ren2013_table4_synthesised_percent.csv");
  const auto counts = [](const Eigen::VectorXd& pct) {
    for (int n = 1; n < 1000; ++n) {
      double total = 0;
      bool fits = true;
      for (Eigen::Index k = 0; k < pct.size(); ++k) {
        const double x = std::round(pct(k) * n / 100);
        fits &= std::abs(100 * x / n - pct(k)) <= 0.05 + 1e-9;
        total += x;
      }
      if (fits && total == n) return n;
    }
    return 0;
  };
  struct Published {
    double low, high;
  } table_v[] = {{-17.1, 12.9}, {-44.7, 14.3}, {-18.2, 11.3}, {-27.7, -1.6}, {12.6, 35.6}};
  for (Eigen::Index i = 0; i < 5; ++i) {
    const double n1 = counts(rec.row(i)), n2 = counts(syn.row(i));
    ASSERT_GT(n1 * n2, 0) << "material " << i;
    const double x1 = std::round(rec(i, i) * n1 / 100), x2 = std::round(syn(i, i) * n2 / 100);
    const Published& p = table_v[i];
    // Every published interval is centred on the difference of the two tables' diagonals.
    EXPECT_NEAR((p.low + p.high) / 2, 100 * (x1 / n1 - x2 / n2), 0.06) << "material " << i;
    // R's prop.test interval (Wald with continuity correction) gives four of the five to the printed
    // digit; wood's (row 0) is the uncorrected Wald interval: the paper disagrees with itself there.
    const Interval ci = wald_difference(x1, n1, x2, n2, /*continuity_correction=*/i != 0);
    EXPECT_NEAR(100 * ci.low, p.low, 0.1) << "material " << i;
    EXPECT_NEAR(100 * ci.high, p.high, 0.1) << "material " << i;
    if (i == 0) {
      const Interval corrected = wald_difference(x1, n1, x2, n2, true);
      EXPECT_GT(std::abs(100 * corrected.low - p.low), 1.0);
    }
    // Newcombe's interval, which the command gives by default, is not symmetric and is not Table V.
    const Interval nc = newcombe_difference(x1, n1, x2, n2);
    EXPECT_GT(std::abs(100 * nc.low - p.low) + std::abs(100 * nc.high - p.high), 0.2) << "material " << i;
  }
}
