// Exact binomial test and Clopper-Pearson interval, as R's stats::binom.test: proportion correct in
// A/B, 2AFC and ABX blocks against chance, and preference counts against 50 %.
//
//   greater:   p = P(X >= x),  less: p = P(X <= x)  for X ~ Bin(n, p0)
//   two-sided: the probability of every outcome no more likely than the observed one,
//              sum over y with P(y) <= P(x) (1 + 1e-7)   (R's rule, relative tolerance 1e-7)
//   Clopper-Pearson (1934) interval at level 1 - alpha:
//     [Beta^-1(alpha/2; x, n - x + 1), Beta^-1(1 - alpha/2; x + 1, n - x)]  (0 / 1 at the ends);
//     one-sided alternatives use the matching one-sided bound at level 1 - alpha.
#pragma once

namespace ms {

enum class Alternative { two_sided, greater, less };

struct BinomialTest {
  double successes = 0, trials = 0;
  double proportion = 0;
  double p = 1;
  double ci_low = 0, ci_high = 1;
};

BinomialTest binomial_test(unsigned successes, unsigned trials, double p0 = 0.5,
                           Alternative alternative = Alternative::two_sided, double conf_level = 0.95);

}  // namespace ms
