// Two-sample t-tests as R's stats::t.test computes them: paired, Welch (unequal variances) and
// Student (pooled variance); two-sided p and a confidence interval for the mean difference x - y.
//
//   paired:  d_i = x_i - y_i, t = mean(d) / (sd(d)/sqrt(n)), df = n - 1
//   Welch:   se^2 = s_x^2/n_x + s_y^2/n_y, t = (mean x - mean y)/se,
//            df = se^4 / ((s_x^2/n_x)^2/(n_x-1) + (s_y^2/n_y)^2/(n_y-1))   (Welch 1947; Satterthwaite)
//   Student: s_p^2 = ((n_x-1)s_x^2 + (n_y-1)s_y^2)/(n_x+n_y-2), se^2 = s_p^2 (1/n_x + 1/n_y), df = n_x+n_y-2
//   p = 2 P(T_df > |t|); CI = diff +- t_{df,(1+level)/2} se.
// Values are scaled by a power of two near the largest |value| first, so data like 1e300 give exact
// results. Constant data (se = 0, where t is 0/0 or infinite) and results beyond the double range
// throw std::domain_error, as R's t.test refuses "data are essentially constant".
#pragma once
#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

struct TTest {
  double t = 0, df = 0, p = 1;
  double mean_diff = 0;  // mean(x) - mean(y) (paired: mean of the differences)
  double se = 0;         // standard error of mean_diff
  double ci_low = 0, ci_high = 0;
  double conf_level = 0.95;
};

// x and y of equal length, pairs at the same index; n >= 2.
TTest paired_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level = 0.95);
// Independent samples, each with at least two values.
TTest welch_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level = 0.95);
TTest student_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level = 0.95);

// Two-sided p of a t statistic: 2 P(T_df > |t|).
double t_two_sided_p(double t, double df);

// The two samples of a t-test read from a tidy table, one row per observation: `group` has exactly
// two levels (first and second in order of first appearance; the difference is first - second).
// Paired: one value per subject and level, the mean of its rows (as afex aggregates), subjects in
// order of first appearance. InputError at the cell for a third or a single level, a subject without
// an observation of a level, fewer than two subjects (paired) or observations per level (otherwise).
struct TTestColumns {
  std::string dv, group, subject;  // subject: needed when paired
  bool paired = false;
};
struct TTestSamples {
  std::vector<std::string> levels;  // the two levels of `group`
  std::vector<double> first, second;
  bool averaged = false;  // paired: a subject had more than one observation of a level
};
TTestSamples t_test_samples_from_table(const TidyCsv& table, const TTestColumns& columns);

}  // namespace ms
