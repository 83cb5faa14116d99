#include "analysis/stats/signal_detection.hpp"

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <functional>
#include <limits>

namespace ms {

namespace {

constexpr double kSqrt2 = 1.4142135623730950488;

// Increasing f on [0, hi]: the d with f(d) = target, by bisection to full double precision.
double invert_increasing(const std::function<double(double)>& f, double target, double hi) {
  double lo = 0.0;
  if (target <= f(lo)) return 0.0;
  if (target >= f(hi)) return std::numeric_limits<double>::infinity();
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double normal_cdf(double x) { return 0.5 * std::erfc(-x / kSqrt2); }

double normal_quantile(double p) {
  if (p <= 0) return -std::numeric_limits<double>::infinity();
  if (p >= 1) return std::numeric_limits<double>::infinity();
  return boost::math::quantile(boost::math::normal(), p);
}

double dprime_yes_no(double hit_rate, double false_alarm_rate) {
  return normal_quantile(hit_rate) - normal_quantile(false_alarm_rate);
}

double pc_2afc(double dprime) { return normal_cdf(dprime / kSqrt2); }
double dprime_2afc(double pc) { return kSqrt2 * normal_quantile(pc); }

double pc_abx(double dprime) {
  return normal_cdf(dprime / kSqrt2) * normal_cdf(dprime / 2) + normal_cdf(-dprime / kSqrt2) * normal_cdf(-dprime / 2);
}

double dprime_abx(double pc) { return invert_increasing(pc_abx, pc, 40.0); }

double hit_rate_same_different(double dprime, double criterion_k) {
  return normal_cdf((dprime - criterion_k) / kSqrt2) + normal_cdf((-dprime - criterion_k) / kSqrt2);
}

SameDifferent dprime_same_different(double hit_rate, double false_alarm_rate) {
  SameDifferent r;
  // F = 2 Phi(-k / sqrt2)  =>  k = -sqrt2 z(F / 2).
  r.criterion_k = -kSqrt2 * normal_quantile(false_alarm_rate / 2);
  const double k = r.criterion_k;
  r.dprime = invert_increasing([k](double d) { return hit_rate_same_different(d, k); }, hit_rate, 80.0);
  return r;
}

double corrected_rate(double k, double n) {
  if (k <= 0) return 0.5 / n;
  if (k >= n) return 1 - 0.5 / n;
  return k / n;
}

}  // namespace ms
