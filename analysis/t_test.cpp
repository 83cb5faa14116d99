#include "analysis/t_test.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ms {

namespace {

struct Moments {
  double n = 0, mean = 0, var = 0;  // var: unbiased (n - 1)
};

Moments moments(const std::vector<double>& v) {
  Moments m;
  m.n = double(v.size());
  for (double x : v) m.mean += x;
  m.mean /= m.n;
  for (double x : v) m.var += (x - m.mean) * (x - m.mean);
  m.var /= m.n - 1;
  return m;
}

TTest finish(double diff, double se, double df, double conf_level) {
  TTest r;
  r.mean_diff = diff;
  r.se = se;
  r.df = df;
  r.conf_level = conf_level;
  r.t = se > 0 ? diff / se : (diff == 0 ? std::numeric_limits<double>::quiet_NaN()
                                        : std::copysign(std::numeric_limits<double>::infinity(), diff));
  r.p = t_two_sided_p(r.t, df);
  const double q = boost::math::quantile(boost::math::students_t(df), 0.5 + conf_level / 2);
  r.ci_low = diff - q * se;
  r.ci_high = diff + q * se;
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
  std::vector<double> d(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) d[i] = x[i] - y[i];
  const Moments m = moments(d);
  return finish(m.mean, std::sqrt(m.var / m.n), m.n - 1, conf_level);
}

TTest welch_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level) {
  if (x.size() < 2 || y.size() < 2) throw std::invalid_argument("Welch t-test needs two values per group");
  const Moments a = moments(x), b = moments(y);
  const double vx = a.var / a.n, vy = b.var / b.n;
  const double se2 = vx + vy;
  const double df = se2 * se2 / (vx * vx / (a.n - 1) + vy * vy / (b.n - 1));
  return finish(a.mean - b.mean, std::sqrt(se2), df, conf_level);
}

TTest student_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level) {
  if (x.size() < 2 || y.size() < 2) throw std::invalid_argument("Student t-test needs two values per group");
  const Moments a = moments(x), b = moments(y);
  const double df = a.n + b.n - 2;
  const double pooled = ((a.n - 1) * a.var + (b.n - 1) * b.var) / df;
  return finish(a.mean - b.mean, std::sqrt(pooled * (1 / a.n + 1 / b.n)), df, conf_level);
}

}  // namespace ms
