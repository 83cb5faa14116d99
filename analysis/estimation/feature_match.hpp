// The feature-domain metric of Ren et al. (patent US 9,401,684 Sec. 5.2.2, Eqs. 20-26, App. C): modes
// as points (c_z Z(f), c_d / d) with Z the Wang-Sekey-Gersho Bark map, a point-to-point match score
// k(D) of their distance, the set-to-set match ratios of the reference and estimated sets, and their
// product (the Match Ratio Product, negated so that lower is better).
#pragma once
#include <vector>

namespace ms {

struct FeatureMatchConstants {
  double c_z = 5.0;    // per Bark (Eq. 21)
  double c_d = 100.0;  // 1/s (Eq. 22: Y(d) = c_d / d, the mode's duration scaled)
};

// A mode as the metric sees it; weight is its perceptual importance (omega in Eqs. 23 and 25; see
// perceptual_metric.hpp for the loudness weights the estimation uses).
struct FeaturePoint {
  double freq_hz = 0.0;
  double decay_per_s = 0.0;
  double weight = 1.0;
};

// Eq. 20: D = ||(c_z Z(f1), c_d/d1) - (c_z Z(f2), c_d/d2)||; +infinity when a decay is not positive
// (a mode without a duration in this space matches nothing).
double feature_distance(const FeaturePoint& a, const FeaturePoint& b, const FeatureMatchConstants& c = {});

// Eq. 31: k(D) = 1 - 0.5 D (D <= 1); 0.5 / D (1 < D <= 5); 0 (D > 5).
double point_match_score(double distance);

// Eq. 24 with App. C's u_ij = 1 where k > 0, else 0: the mean of the positive scores of p against the
// points of `set`, 0 when none is positive.
double point_to_set_match(const FeaturePoint& p, const std::vector<FeaturePoint>& set,
                          const FeatureMatchConstants& c = {});

// Eq. 23 (and Eq. 25 with the roles swapped): sum_i w_i R(p_i, other) / sum_i w_i over `points`;
// 0 when the weights sum to 0 (no audible point).
double set_match_ratio(const std::vector<FeaturePoint>& points, const std::vector<FeaturePoint>& other,
                       const FeatureMatchConstants& c = {});

struct MatchRatios {
  double reference = 0.0;  // R(Phi, Phi~): how well the reference points are matched
  double estimate = 0.0;   // R~(Phi, Phi~): how well the estimated points are matched
  double product = 0.0;    // Pi_MRP = -R R~ (Eq. 26), in [-1, 0]
};
MatchRatios match_ratio_product(const std::vector<FeaturePoint>& reference,
                                const std::vector<FeaturePoint>& estimate, const FeatureMatchConstants& c = {});

}  // namespace ms
