// Point and set match scores of the feature-domain metric; see feature_match.hpp.
#include "analysis/estimation/feature_match.hpp"

#include <cmath>
#include <cstddef>
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

namespace {

// A point's coordinates in the metric's plane, (c_z Z(f), c_d / d), computed once per point so that
// the all-pairs match costs no Bark map per pair; with the same arithmetic as feature_distance.
struct PlanePoint {
  double z, y, weight;
  bool has_duration;
};

void to_plane(const std::vector<FeaturePoint>& points, const FeatureMatchConstants& c, std::vector<PlanePoint>& out) {
  out.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const FeaturePoint& p = points[i];
    out[i] = {bark_wang_sekey_gersho(p.freq_hz), c.c_d / p.decay_per_s, p.weight, p.decay_per_s > 0.0};
  }
}

double plane_set_match_ratio(const std::vector<PlanePoint>& points, const std::vector<PlanePoint>& other,
                             const FeatureMatchConstants& c) {
  double num = 0.0, den = 0.0;
  for (const PlanePoint& p : points) {
    if (!(p.weight > 0.0)) continue;
    double sum = 0.0;
    int matched = 0;
    if (p.has_duration)
      for (const PlanePoint& q : other) {
        if (!q.has_duration) continue;
        const double dx = c.c_z * (p.z - q.z);
        if (std::abs(dx) > 5.0) continue;  // D >= |dx| > 5: k is 0
        const double dy = p.y - q.y;
        const double k = point_match_score(std::sqrt(dx * dx + dy * dy));
        if (k > 0.0) {
          sum += k;
          ++matched;
        }
      }
    num += p.weight * (matched > 0 ? sum / matched : 0.0);
    den += p.weight;
  }
  return den > 0.0 ? num / den : 0.0;
}

}  // namespace

double set_match_ratio(const std::vector<FeaturePoint>& points, const std::vector<FeaturePoint>& other,
                       const FeatureMatchConstants& c) {
  std::vector<PlanePoint> a, b;
  to_plane(points, c, a);
  to_plane(other, c, b);
  return plane_set_match_ratio(a, b, c);
}

MatchRatios match_ratio_product(const std::vector<FeaturePoint>& reference, const std::vector<FeaturePoint>& estimate,
                                const FeatureMatchConstants& c) {
  thread_local std::vector<PlanePoint> ref_plane, est_plane;  // reused: the estimation calls this per candidate
  to_plane(reference, c, ref_plane);
  to_plane(estimate, c, est_plane);
  MatchRatios r;
  r.reference = plane_set_match_ratio(ref_plane, est_plane, c);
  r.estimate = plane_set_match_ratio(est_plane, ref_plane, c);
  r.product = -r.reference * r.estimate;
  return r;
}

}  // namespace ms
