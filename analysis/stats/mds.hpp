// Multidimensional scaling of a dissimilarity matrix into a K-dimensional perceptual map.
//
// Classical (Torgerson 1952; Gower 1966; R's stats::cmdscale):
//   B = -1/2 J D^(2) J with J = I - 11'/n and D^(2) the squared dissimilarities;
//   X = V_K Lambda_K^(1/2) from the K largest eigenvalues of B (negative ones give zero columns).
// Metric SMACOF (de Leeuw 1977; Borg & Groenen 2005, ch. 8), unit weights: minimise the raw stress
//   sigma(X) = sum_{i<j} (delta_ij - d_ij(X))^2 by the Guttman transform X <- (1/n) B(X) X,
//   B_ij = -delta_ij / d_ij(X) (0 when d_ij = 0), B_ii = -sum_{j != i} B_ij; stops when sigma
//   falls by less than `tolerance` relative, or after `max_iterations`. Several starts: the
//   classical solution and seeded random ones; the lowest stress wins. One iteration is a single
//   allocation-free O(n^2 K) pass (distances, stress and B(X)X together; see mds.cpp).
// Nonmetric SMACOF (Kruskal 1964; Borg & Groenen 2005, ch. 9): each iteration replaces delta by
//   disparities dhat, the least-squares monotone (non-decreasing in delta) regression of the current
//   distances (pool-adjacent-violators; ties in delta kept tied: Kruskal's secondary approach),
//   scaled so that sum dhat^2 = n(n-1)/2; then one Guttman transform with dhat. Stress-1 is
//   sqrt(sum (d - dhat)^2 / sum d^2), as MASS::isoMDS reports it (there in percent).
// Kruskal's stress-1 of a configuration (Kruskal 1964), with the disparities b delta at the optimal
// ratio scale b = sum delta d / sum delta^2 (so it does not depend on the units of delta):
//   S1 = sqrt( sum_{i<j} (d_ij - b delta_ij)^2 / sum_{i<j} d_ij^2 ).
// Configurations are centred; their rotation and reflection are arbitrary.
#pragma once
#include <Eigen/Dense>

#include <cstdint>
#include <vector>

namespace ms {

struct ClassicalMds {
  Eigen::MatrixXd points;       // n x K
  Eigen::VectorXd eigenvalues;  // all n eigenvalues of B, descending
};
ClassicalMds classical_mds(const Eigen::MatrixXd& dissimilarity, int dims);

struct SmacofOptions {
  int dims = 2;
  int random_starts = 3;  // in addition to the classical start: 4 starts, as scikit-learn's n_init
  std::uint64_t seed = 1;
  // Per start. The defaults match scikit-learn's max_iter = 300 and are far tighter than its
  // eps = 1e-3 (its test is (sigma_old - sigma)/sum_i |x_i| < eps); on the 100-stimulus comparison
  // matrix (tests/data/mds/sklearn_compare.py) the classical start alone converges in < 50
  // iterations to a lower stress-1 than scikit-learn's best of 4 starts.
  int max_iterations = 300;
  double tolerance = 1e-8;  // relative decrease of raw stress
};

struct SmacofResult {
  Eigen::MatrixXd points;  // n x K
  double raw_stress = 0;   // sigma(X)
  double stress1 = 0;      // Kruskal's stress-1
  int iterations = 0;      // of the winning start
  int best_start = 0;      // 0 = classical, 1.. = random
};
SmacofResult smacof(const Eigen::MatrixXd& dissimilarity, const SmacofOptions& options);
SmacofResult smacof_nonmetric(const Eigen::MatrixXd& dissimilarity, const SmacofOptions& options);

// Least-squares fit of y by a non-decreasing sequence (pool adjacent violators), unit weights.
std::vector<double> monotone_regression(const std::vector<double>& y);

// Euclidean distances between the rows of `points`.
Eigen::MatrixXd pairwise_distances(const Eigen::MatrixXd& points);
double raw_stress(const Eigen::MatrixXd& dissimilarity, const Eigen::MatrixXd& points);
double stress1(const Eigen::MatrixXd& dissimilarity, const Eigen::MatrixXd& points);

}  // namespace ms
