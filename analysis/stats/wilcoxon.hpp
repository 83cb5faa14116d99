// Wilcoxon signed-rank test of paired samples (or one sample against mu), as R's
// stats::wilcox.test(x, y, paired = TRUE, mu, exact, correct) computes it (R 4.2), and the sign test.
//
//   d_i = x_i - y_i - mu; zeros dropped (n counts the non-zero d); ranks r_i of |d_i| (ties get the
//   mean rank); V = sum of r_i over d_i > 0.
//   Exact (Wilcoxon 1945), used when requested or by default when n < 50, and only if there are
//   no ties and no zeros: under H0, V is the sum of a random subset of {1..n}; its distribution is
//   counted by dynamic programming (R's csignrank).
//     two-sided: p = min(1, 2 P(V >= v)) if v > n(n+1)/4, else min(1, 2 P(V <= v));
//     greater: P(V >= v); less: P(V <= v).
//   Otherwise the normal approximation with tie correction (and continuity correction when
//   `correct`):  z = (V - n(n+1)/4 - c) / sigma,
//     sigma^2 = n(n+1)(2n+1)/24 - sum_t (t^3 - t)/48   (t: sizes of the groups of tied |d|),
//     c = 0.5 sign(V - n(n+1)/4) two-sided, +0.5 greater, -0.5 less (0 without correction);
//     two-sided p = 2 min(Phi(z), 1 - Phi(z)).
//   Like R, "exact" with ties or zeros falls back to the normal approximation (exact = false in
//   the result says which was used).
// Sign test (Dixon & Mood 1946): the number of positive d among the non-zero ones against
// Bin(n, 1/2), via binomial_test (R's binom.test).
#pragma once
#include <vector>

#include "analysis/stats/binomial_test.hpp"

namespace ms {

enum class ExactMode { automatic, exact, normal };  // R: exact = NULL, TRUE, FALSE

struct WilcoxonOptions {
  Alternative alternative = Alternative::two_sided;
  ExactMode exact = ExactMode::automatic;
  bool correct = true;  // continuity correction of the normal approximation
  double mu = 0;
};

struct WilcoxonResult {
  double v = 0;         // R's statistic V
  int n = 0;            // non-zero differences
  int zeros = 0;        // dropped differences
  bool ties = false;    // tied |d| among the non-zero ones
  bool exact = false;   // exact distribution used
  double z = 0;         // normal approximation only (NaN when exact)
  double p = 1;
};

// x and y of equal length (std::invalid_argument otherwise); at least one non-zero difference.
WilcoxonResult wilcoxon_signed_rank(const std::vector<double>& x, const std::vector<double>& y,
                                    const WilcoxonOptions& options = {});
// One sample against options.mu.
WilcoxonResult wilcoxon_signed_rank(const std::vector<double>& x, const WilcoxonOptions& options = {});

// P(V <= v) for the signed-rank statistic of n untied non-zero differences (R's psignrank).
double signed_rank_cdf(double v, int n);

struct SignTest {
  int positive = 0, negative = 0, zeros = 0;
  double p = 1;  // binomial_test(positive, positive + negative, 0.5, alternative)
};
SignTest sign_test(const std::vector<double>& x, const std::vector<double>& y,
                   Alternative alternative = Alternative::two_sided);

}  // namespace ms
