#include "analysis/t_test.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ms {

namespace {

struct Moments {
  double n = 0, mean = 0, var = 0;  // var: unbiased (n - 1)
};

// Power of two bringing the largest |value| near 1: exact, and keeps squares of values like 1e300
// inside the double range (t, df and p do not depend on it).
double scale_of(const std::vector<double>& x, const std::vector<double>& y) {
  double m = 0;
  for (double v : x) m = std::max(m, std::abs(v));
  for (double v : y) m = std::max(m, std::abs(v));
  return m > 0 ? std::ldexp(1.0, std::ilogb(m)) : 1.0;
}

Moments moments(const std::vector<double>& v, double scale) {
  Moments m;
  m.n = double(v.size());
  for (double x : v) m.mean += x / scale;
  m.mean /= m.n;
  for (double x : v) m.var += (x / scale - m.mean) * (x / scale - m.mean);
  m.var /= m.n - 1;
  return m;
}

// diff and se in units of `scale`.
TTest finish(double diff, double se, double df, double conf_level, double scale) {
  if (!(se > 0)) throw std::domain_error("the data are constant (standard error 0): no t statistic");
  TTest r;
  r.df = df;
  r.conf_level = conf_level;
  r.t = diff / se;
  r.p = t_two_sided_p(r.t, df);
  const double q = boost::math::quantile(boost::math::students_t(df), 0.5 + conf_level / 2);
  r.mean_diff = diff * scale;
  r.se = se * scale;
  r.ci_low = (diff - q * se) * scale;
  r.ci_high = (diff + q * se) * scale;
  for (double v : {r.t, r.df, r.p, r.mean_diff, r.se, r.ci_low, r.ci_high})
    if (!std::isfinite(v)) throw std::domain_error("the interval exceeds the range of double precision");
  return r;
}

}  // namespace

double t_two_sided_p(double t, double df) {
  if (std::isnan(t)) return std::numeric_limits<double>::quiet_NaN();
  if (std::isinf(t)) return 0.0;
  return 2 * boost::math::cdf(boost::math::complement(boost::math::students_t(df), std::abs(t)));
}

TTest paired_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level) {
  if (x.size() != y.size() || x.size() < 2) throw std::invalid_argument("paired t-test needs n >= 2 pairs");
  const double s = scale_of(x, y);
  std::vector<double> d(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) d[i] = x[i] / s - y[i] / s;  // scaled first: no overflow
  const Moments m = moments(d, 1.0);
  if (!(m.var > 0)) throw std::domain_error("the differences are all equal (standard deviation 0): no t statistic");
  return finish(m.mean, std::sqrt(m.var / m.n), m.n - 1, conf_level, s);
}

TTest welch_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level) {
  if (x.size() < 2 || y.size() < 2) throw std::invalid_argument("Welch t-test needs two values per group");
  const double s = scale_of(x, y);
  const Moments a = moments(x, s), b = moments(y, s);
  const double vx = a.var / a.n, vy = b.var / b.n;
  const double se2 = vx + vy;
  if (!(se2 > 0)) throw std::domain_error("both groups are constant (standard deviation 0): no t statistic");
  const double df = se2 * se2 / (vx * vx / (a.n - 1) + vy * vy / (b.n - 1));
  return finish(a.mean - b.mean, std::sqrt(se2), df, conf_level, s);
}

TTest student_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level) {
  if (x.size() < 2 || y.size() < 2) throw std::invalid_argument("Student t-test needs two values per group");
  const double s = scale_of(x, y);
  const Moments a = moments(x, s), b = moments(y, s);
  const double df = a.n + b.n - 2;
  const double pooled = ((a.n - 1) * a.var + (b.n - 1) * b.var) / df;
  if (!(pooled > 0)) throw std::domain_error("both groups are constant (standard deviation 0): no t statistic");
  return finish(a.mean - b.mean, std::sqrt(pooled * (1 / a.n + 1 / b.n)), df, conf_level, s);
}

}  // namespace ms
