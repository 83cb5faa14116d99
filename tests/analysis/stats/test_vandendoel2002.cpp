// The published tables of van den Doel, Pai, Adam, Kortchmar & Pichora-Fuller (2002),
// "Measurements of perceptual quality of contact sound models" (ICAD), recomputed by our statistics:
// Table 1 (optimal masking threshold a_v per subject) and Table 2 (tokens distinguished per subject in
// each of the four sequences, read against their ceilings). Golden values:
// tests/data/vandendoel2002/make_golden.R.
#include <gtest/gtest.h>

#include "analysis/stats/distinguished_tokens.hpp"
#include "analysis/stats/quantile.hpp"
#include "synthesis/tidy_csv.hpp"
#include "analysis/stats/wilcoxon.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/vandendoel2002/";

std::vector<double> column(const TidyCsv& t, const std::string& name, const std::string& filter_col = "",
                           const std::string& filter = "") {
  std::vector<double> v;
  const std::size_t c = t.column(name);
  for (std::size_t r = 0; r < t.rows(); ++r)
    if (filter_col.empty() || t.cell(r, t.column(filter_col)) == filter) v.push_back(t.number(r, c));
  return v;
}

double golden_median(const std::string& what) {
  const TidyCsv g = TidyCsv::read(kDir + "medians_golden.csv");
  for (std::size_t r = 0; r < g.rows(); ++r)
    if (g.cell(r, 0) == what) return g.number(r, 1);
  ADD_FAILURE() << "no golden median for " << what;
  return 0;
}

}  // namespace

// Table 1's optimal a_v range from 3 to 20 dB; the paper took their median over both objects, 16 dB
// (sec. 4), as the threshold of the stimuli of Experiments 2 and 3.
TEST(VanDenDoel2002, Table1MedianThresholds) {
  const TidyCsv t = TidyCsv::read(kDir + "table1_av.csv");
  ASSERT_EQ(t.rows(), 16u);
  const std::vector<double> vase = column(t, "av_db", "object", "vase"), bowl = column(t, "av_db", "object", "bowl");
  ASSERT_EQ(vase, (std::vector<double>{5, 16, 15, 17, 14, 18, 15, 3}));
  ASSERT_EQ(bowl, (std::vector<double>{13, 19, 17, 20, 20, 13, 16, 19}));
  EXPECT_EQ(median(vase), 15.0);
  EXPECT_EQ(median(bowl), 18.0);
  EXPECT_EQ(median(column(t, "av_db")), 16.0);
  EXPECT_EQ(median(vase), golden_median("vase"));
  EXPECT_EQ(median(bowl), golden_median("bowl"));
  EXPECT_EQ(median(column(t, "av_db")), golden_median("pooled"));
  // Table 1's range.
  EXPECT_EQ(quantile(column(t, "av_db"), 0), 3.0);
  EXPECT_EQ(quantile(column(t, "av_db"), 1), 20.0);
}

// Table 2 is the number of tokens each subject distinguished in Experiment 2's adaptive procedure (the
// references in turn), not a number of modes needed: each sequence has its own ceiling, its number of
// tokens - 179 (vase, naive), 100 (vase, energy), 128 (bowl, naive), 41 (bowl, energy). Medians per column
// and their shares of the ceiling, through the same summary `stats tokens` prints.
TEST(VanDenDoel2002, Table2DistinguishedTokensAgainstTheirCeilings) {
  const TidyCsv t = TidyCsv::read(kDir + "table2_tokens.csv");
  ASSERT_EQ(t.rows(), 8u);
  const std::vector<double> vn = column(t, "Vn"), ve = column(t, "Ve"), bn = column(t, "Bn"), be = column(t, "Be");
  EXPECT_EQ(vn, (std::vector<double>{64, 27, 25, 12, 79, 59, 78, 12}));
  EXPECT_EQ(be, (std::vector<double>{3, 2, 3, 4, 15, 8, 15, 4}));
  const std::pair<const char*, int> ceilings[] = {{"Vn", 179}, {"Ve", 100}, {"Bn", 128}, {"Be", 41}};
  std::vector<TokenCount> counts;
  for (const auto& [c, ceiling] : ceilings)
    for (std::size_t r = 0; r < t.rows(); ++r) {
      const double n = t.number(r, t.column(c));
      EXPECT_LE(n, ceiling) << c;  // a count cannot pass its sequence's number of tokens
      counts.push_back({"", t.cell(r, t.column("subject")), c, int(n), ceiling});
    }
  const TokensTable table = tokens_table(counts);
  ASSERT_EQ(table.summary.size(), 4u);
  const double medians[] = {43, 19, 10, 4};
  for (std::size_t k = 0; k < 4; ++k) {
    SCOPED_TRACE(table.summary[k].name);
    EXPECT_EQ(table.summary[k].median, medians[k]);
    EXPECT_EQ(table.summary[k].median, golden_median(table.summary[k].name));
    EXPECT_EQ(table.summary[k].tokens_min, ceilings[k].second);
  }
  // The medians as shares of the ceilings: 43/179, 19/100, 10/128, 4/41 (by hand: the median of the
  // subjects' shares is the median count over the ceiling, one ceiling per column).
  EXPECT_NEAR(table.summary[0].median_share, 43.0 / 179.0, 1e-12);
  EXPECT_NEAR(table.summary[1].median_share, 0.19, 1e-12);
  EXPECT_NEAR(table.summary[2].median_share, 10.0 / 128.0, 1e-12);
  EXPECT_NEAR(table.summary[3].median_share, 4.0 / 41.0, 1e-12);
}

// A paired test of naive against energy counts is confounded by the ceilings: the energy sequences are
// shorter (100 < 179, 41 < 128), so fewer energy tokens are expected before any listener is asked. On
// counts, naive exceeds energy for 6 of 8 subjects (vase) and 6 of the 6 that differ (bowl); on shares of
// the ceiling, for 4 of 8 and 3 of 8. The signed-rank and sign tests below are kept as checks of
// analysis/wilcoxon on numbers with ties (vase: |d| = 1 twice) and zeros (bowl: subjects 1 and 3)
// against R - not as a result of the paper.
TEST(VanDenDoel2002, Table2PairedTestIsConfoundedByTheCeilings) {
  const TidyCsv t = TidyCsv::read(kDir + "table2_tokens.csv");
  const std::vector<double> vn = column(t, "Vn"), ve = column(t, "Ve"), bn = column(t, "Bn"), be = column(t, "Be");
  const auto naive_above = [](const std::vector<double>& naive, double naive_ceiling, const std::vector<double>& energy,
                              double energy_ceiling) {
    int n = 0;
    for (std::size_t i = 0; i < naive.size(); ++i) n += naive[i] / naive_ceiling > energy[i] / energy_ceiling;
    return n;
  };
  EXPECT_EQ(naive_above(vn, 1, ve, 1), 6);
  EXPECT_EQ(naive_above(bn, 1, be, 1), 6);
  EXPECT_EQ(naive_above(vn, 179, ve, 100), 4);  // shares: no direction left
  EXPECT_EQ(naive_above(bn, 128, be, 41), 3);   // shares: energy ahead for 5 of 8

  const TidyCsv g = TidyCsv::read(kDir + "table2_tests_golden.csv");
  ASSERT_EQ(g.rows(), 2u);
  const std::pair<const std::vector<double>*, const std::vector<double>*> pairs[] = {{&vn, &ve}, {&bn, &be}};
  for (std::size_t r = 0; r < 2; ++r) {
    SCOPED_TRACE(g.cell(r, 0));
    const auto& [naive, energy] = pairs[r];
    // Ties and zeros rule out the exact test, as in R.
    const WilcoxonResult w = wilcoxon_signed_rank(*naive, *energy);
    EXPECT_FALSE(w.exact);
    EXPECT_DOUBLE_EQ(w.v, g.number(r, g.column("V")));
    const double p = g.number(r, g.column("p"));
    EXPECT_NEAR(w.p, p, 1e-10 * p);
    WilcoxonOptions o;
    o.exact = ExactMode::normal;
    o.correct = false;
    const double pu = g.number(r, g.column("p_uncorrected"));
    EXPECT_NEAR(wilcoxon_signed_rank(*naive, *energy, o).p, pu, 1e-10 * pu);
    const SignTest s = sign_test(*naive, *energy);
    EXPECT_EQ(s.positive, int(g.number(r, g.column("sign_positive"))));
    EXPECT_EQ(s.positive + s.negative, int(g.number(r, g.column("sign_n"))));
    const double sp = g.number(r, g.column("sign_p"));
    EXPECT_NEAR(s.p, sp, 1e-10 * sp);
  }
  EXPECT_NEAR(wilcoxon_signed_rank(vn, ve).p, 0.0925, 5e-5);
  EXPECT_NEAR(wilcoxon_signed_rank(bn, be).p, 0.0355, 5e-5);
  EXPECT_DOUBLE_EQ(sign_test(bn, be).p, 0.03125);
}
