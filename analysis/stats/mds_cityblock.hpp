// Metric MDS with city-block distances d_ij = sum_k |x_ik - x_jk| (van den Doel et al. 2002 also drew
// their perceptual maps in the city-block metric). Raw stress sigma = sum_{i<j} (delta_ij - d_ij)^2 is
// minimised by majorization (Heiser 1991; Groenen, Mathar & Heiser 1995): at the current Y,
//   -d_ij(X) <= -sum_k s_ijk (x_ik - x_jk),           s_ijk = sign(y_ik - y_jk)
//   d_ij(X)^2 <= d_ij(Y) sum_k (x_ik - x_jk)^2 / |y_ik - y_jk|   (Cauchy-Schwarz, equality at X = Y)
// so each dimension k is updated by the weighted least-squares system L_k x_k = b_k with
//   L_k = sum_{i<j} a_ijk (e_i - e_j)(e_i - e_j)',  a_ijk = d_ij(Y) / max(|y_ik - y_jk|, eps),
//   b_k = sum_{i<j} delta_ij s_ijk (e_i - e_j),
// solved on the centred subspace. The city-block metric is not rotation invariant: the starts are the
// Euclidean SMACOF map rotated in 15 degree steps (2-D) plus seeded random configurations.
#pragma once
#include <Eigen/Dense>

#include "analysis/stats/mds.hpp"

namespace ms {

Eigen::MatrixXd pairwise_cityblock(const Eigen::MatrixXd& points);

// Kruskal's stress-1 with city-block distances (as stress1 in mds.hpp, optimal ratio scale).
double stress1_cityblock(const Eigen::MatrixXd& dissimilarity, const Eigen::MatrixXd& points);

SmacofResult smacof_cityblock(const Eigen::MatrixXd& dissimilarity, const SmacofOptions& options);

}  // namespace ms
