// Post-hoc pairwise comparisons after a repeated-measures ANOVA, as R's pairwise.t.test computes them
// on the subjects' marginal means (the cell means of rm_data averaged over the other factors):
//
//   within factor:  a paired t-test for every pair of levels (pairwise.t.test(paired = TRUE));
//   between factor: a t-test for every pair of groups with the standard deviation pooled over all
//                   groups, s_p^2 = sum_g (n_g - 1) s_g^2 / (N - G), df = N - G (pool.sd = TRUE, R's
//                   default when unpaired), t = (mean_a - mean_b) / (s_p sqrt(1/n_a + 1/n_b)).
//
// p values are adjusted over the family of all pairs of the factor, as stats::p.adjust does:
//   bonferroni: p_(i) * m, capped at 1;
//   holm:       sorted ascending, p_(i) * (m - i + 1), made monotone by a running maximum, capped at 1
//               (Holm 1979: uniformly more powerful than Bonferroni, same family-wise error control).
#pragma once
#include <string>
#include <vector>

#include "analysis/stats/rm_data.hpp"

namespace ms {

enum class PAdjust { none, holm, bonferroni };

// The name as R's p.adjust spells it ("none", "holm", "bonferroni"), and back (nullopt-free: throws
// std::invalid_argument naming the accepted names).
const char* p_adjust_name(PAdjust method);
PAdjust p_adjust_from_name(const std::string& name);

// Adjusted p values, in the order given.
std::vector<double> p_adjust(const std::vector<double>& p, PAdjust method);

struct PairwiseComparison {
  std::string level_a, level_b;  // a before b in the factor's level order
  double mean_diff = 0;          // marginal mean of a minus that of b
  double t = 0, df = 0;
  double p = 1;                  // unadjusted two-sided
  double p_adjusted = 1;
};

struct Posthoc {
  std::string factor;
  bool within = true;
  PAdjust method = PAdjust::holm;
  std::vector<PairwiseComparison> pairs;  // (0,1), (0,2), ..., (1,2), ... in level order
};

// Every pair of levels of the named factor of `data` (a within or a between factor). Throws
// std::invalid_argument for a factor the design does not have, std::domain_error where a pair's
// differences are constant (t undefined, as R's t.test refuses).
Posthoc pairwise_t_tests(const RmData& data, const std::string& factor, PAdjust method);

}  // namespace ms
