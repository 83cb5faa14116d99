// Point and set match scores of the feature-domain metric; see feature_match.hpp.
#include "analysis/estimation/feature_match.hpp"

#include <cmath>
#include <limits>

#include "synthesis/bark.hpp"

namespace ms {

double feature_distance(const FeaturePoint& a, const FeaturePoint& b, const FeatureMatchConstants& c) {
  if (!(a.decay_per_s > 0.0) || !(b.decay_per_s > 0.0)) return std::numeric_limits<double>::infinity();
  const double dx = c.c_z * (bark_wang_sekey_gersho(a.freq_hz) - bark_wang_sekey_gersho(b.freq_hz));
  const double dy = c.c_d / a.decay_per_s - c.c_d / b.decay_per_s;
  return std::sqrt(dx * dx + dy * dy);  // no overflow to guard against here; hypot costs several times more
}

double point_match_score(double d) {
  if (d <= 1.0) return 1.0 - 0.5 * d;
  if (d <= 5.0) return 0.5 / d;
  return 0.0;
}

double point_to_set_match(const FeaturePoint& p, const std::vector<FeaturePoint>& set, const FeatureMatchConstants& c) {
  double sum = 0.0;
  int matched = 0;
  for (const FeaturePoint& q : set) {
    const double k = point_match_score(feature_distance(p, q, c));
    if (k > 0.0) {
      sum += k;
      ++matched;
    }
  }
  return matched > 0 ? sum / matched : 0.0;
}

double set_match_ratio(const std::vector<FeaturePoint>& points, const std::vector<FeaturePoint>& other,
                       const FeatureMatchConstants& c) {
  double num = 0.0, den = 0.0;
  for (const FeaturePoint& p : points) {
    if (!(p.weight > 0.0)) continue;
    num += p.weight * point_to_set_match(p, other, c);
    den += p.weight;
  }
  return den > 0.0 ? num / den : 0.0;
}

MatchRatios match_ratio_product(const std::vector<FeaturePoint>& reference, const std::vector<FeaturePoint>& estimate,
                                const FeatureMatchConstants& c) {
  MatchRatios r;
  r.reference = set_match_ratio(reference, estimate, c);
  r.estimate = set_match_ratio(estimate, reference, c);
  r.product = -r.reference * r.estimate;
  return r;
}

}  // namespace ms
