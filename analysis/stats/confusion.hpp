// Confusion matrices of identification experiments (rows: true class, columns: response) and the
// statistics published with them: row percentages, accuracy, recall, Cohen's kappa, the chi-square
// test of independence, the Frobenius distance between two matrices and Newcombe intervals for
// differences of recognition rates.
//
//   row_percent(i,j) = 100 n_ij / n_i.                 (a row without responses stays 0)
//   accuracy = sum_i n_ii / n;  recall_i = n_ii / n_i.
//   Cohen's kappa (Cohen 1960; sklearn.metrics.cohen_kappa_score):
//     p_o = sum_i n_ii / n, p_e = sum_i n_i. n_.i / n^2, kappa = (p_o - p_e) / (1 - p_e).
//   Pearson chi-square test of independence (scipy.stats.chi2_contingency): E_ij = n_i. n_.j / n,
//     chi2 = sum (n_ij - E_ij)^2 / E_ij over the rows and columns that are not all zero (a label
//     never presented or never answered carries no information and would divide by zero),
//     df = (r - 1)(c - 1); Yates' continuity correction when df = 1, as scipy does by default.
//   Frobenius distance ||A - B||_F = sqrt(sum (a_ij - b_ij)^2) of two row-percent matrices
//     (Sterling et al. 2019 compare identification matrices this way).
//   Wilson score interval (Wilson 1927): centre (x + z^2/2)/(n + z^2),
//     half-width z sqrt(x(n-x)/n + z^2/4)/(n + z^2).
//   Newcombe's hybrid score interval for p1 - p2 (Newcombe 1998, method 10), with Wilson limits
//     (l_k, u_k): [d - sqrt((p1-l1)^2 + (u2-p2)^2), d + sqrt((u1-p1)^2 + (p2-l2)^2)], d = p1 - p2.
#pragma once
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

struct Confusion {
  std::vector<std::string> labels;  // row i and column i are the same class
  Eigen::MatrixXd counts;           // counts(truth, response)
};

// Counts pairs (truth[k], response[k]) over `labels`; every value must be one of the labels.
Confusion confusion_from_pairs(const std::vector<std::string>& labels, const std::vector<std::string>& truth,
                               const std::vector<std::string>& response);

// The (truth, response) pairs of an identification table, one row per response. InputError at the
// cell for an empty label or, when `labels` is not empty, a label not among them; "no data rows".
struct ConfusionResponses {
  std::vector<std::string> truth, response;
};
ConfusionResponses confusion_responses_from_table(const TidyCsv& table, const std::string& truth_column,
                                                  const std::string& response_column,
                                                  const std::vector<std::string>& labels);

Eigen::MatrixXd row_percent(const Eigen::MatrixXd& counts);
double accuracy(const Eigen::MatrixXd& counts);
std::vector<double> recall(const Eigen::MatrixXd& counts);  // NaN for a class never presented
double cohen_kappa(const Eigen::MatrixXd& counts);

struct ChiSquareTest {
  double chi2 = 0, df = 0, p = 1;
  bool yates = false;
};
ChiSquareTest chi2_independence(const Eigen::MatrixXd& counts);

double frobenius_distance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

struct Interval {
  double low = 0, high = 0;
};
// Wilson score interval of x successes in n trials at the given confidence level.
Interval wilson_interval(double x, double n, double conf_level = 0.95);
// Newcombe's hybrid score interval for x1/n1 - x2/n2.
Interval newcombe_difference(double x1, double n1, double x2, double n2, double conf_level = 0.95);
// The Wald interval for p1 - p2 as R's prop.test gives it: d +- (z sqrt(p1 q1/n1 + p2 q2/n2) + y (1/n1 + 1/n2)),
// y = min(1/2, |d| / (1/n1 + 1/n2)) with the continuity correction, 0 without; clipped to [-1, 1].
// Symmetric about d, which is how published tables of this kind (e.g. Ren et al.'s Table V) read.
Interval wald_difference(double x1, double n1, double x2, double n2, bool continuity_correction,
                         double conf_level = 0.95);

}  // namespace ms
