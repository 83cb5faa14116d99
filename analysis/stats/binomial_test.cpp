#include "analysis/stats/binomial_test.hpp"

#include <algorithm>
#include <boost/math/distributions/beta.hpp>
#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <stdexcept>

namespace ms {

namespace {

// P(X <= k) and P(X > k), with k outside [0, n] handled.
double lower(const boost::math::binomial& b, double k) {
  if (k < 0) return 0.0;
  if (k >= b.trials()) return 1.0;
  return boost::math::cdf(b, k);
}
double upper(const boost::math::binomial& b, double k) {
  if (k < 0) return 1.0;
  if (k >= b.trials()) return 0.0;
  return boost::math::cdf(boost::math::complement(b, k));
}

}  // namespace

BinomialTest binomial_test(unsigned successes, unsigned trials, double p0, Alternative alternative, double conf_level) {
  if (trials == 0 || successes > trials) throw std::invalid_argument("binomial_test: need 0 <= x <= n, n > 0");
  const double x = successes, n = trials;
  const boost::math::binomial b(n, p0);
  BinomialTest t;
  t.successes = x;
  t.trials = n;
  t.proportion = x / n;
  switch (alternative) {
    case Alternative::greater: t.p = upper(b, x - 1); break;
    case Alternative::less: t.p = lower(b, x); break;
    case Alternative::two_sided: {
      const double d = boost::math::pdf(b, x);
      const double m = n * p0;
      const double rel = 1 + 1e-7;
      if (x == m) {
        t.p = 1.0;
      } else if (x < m) {
        double y = 0;  // outcomes in the upper tail no more likely than x
        for (double i = std::ceil(m); i <= n; ++i) y += boost::math::pdf(b, i) <= d * rel;
        t.p = lower(b, x) + upper(b, n - y);
      } else {
        double y = 0;
        for (double i = 0; i <= std::floor(m); ++i) y += boost::math::pdf(b, i) <= d * rel;
        t.p = lower(b, y - 1) + upper(b, x - 1);
      }
      t.p = std::min(1.0, t.p);
      break;
    }
  }
  const double alpha = 1 - conf_level;
  auto lo = [&](double a) { return x == 0 ? 0.0 : boost::math::quantile(boost::math::beta_distribution<>(x, n - x + 1), a); };
  auto hi = [&](double a) { return x == n ? 1.0 : boost::math::quantile(boost::math::beta_distribution<>(x + 1, n - x), 1 - a); };
  switch (alternative) {
    case Alternative::two_sided: t.ci_low = lo(alpha / 2); t.ci_high = hi(alpha / 2); break;
    case Alternative::greater: t.ci_low = lo(alpha); t.ci_high = 1.0; break;
    case Alternative::less: t.ci_low = 0.0; t.ci_high = hi(alpha); break;
  }
  return t;
}

}  // namespace ms
