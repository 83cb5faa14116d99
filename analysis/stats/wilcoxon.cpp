#include "analysis/stats/wilcoxon.hpp"

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace ms {

double signed_rank_cdf(double v, int n) {
  if (n < 1) throw std::invalid_argument("signed_rank_cdf: n must be positive");
  const int total = n * (n + 1) / 2;
  const double q = std::floor(v + 1e-7);
  if (q < 0) return 0;
  if (q >= total) return 1;
  // counts[s] = number of subsets of {1..k} with sum s (doubles: exact up to 2^53 subsets).
  std::vector<double> counts(std::size_t(total) + 1, 0.0);
  counts[0] = 1;
  for (int k = 1; k <= n; ++k)
    for (int s = k * (k + 1) / 2; s >= k; --s) counts[std::size_t(s)] += counts[std::size_t(s - k)];
  double below = 0;
  for (int s = 0; s <= int(q); ++s) below += counts[std::size_t(s)];
  return below / std::ldexp(1.0, n);
}

namespace {

WilcoxonResult signed_rank_of(std::vector<double> d, const WilcoxonOptions& o) {
  WilcoxonResult r;
  const std::size_t all = d.size();
  d.erase(std::remove(d.begin(), d.end(), 0.0), d.end());
  r.zeros = int(all - d.size());
  r.n = int(d.size());
  if (r.n == 0) throw std::invalid_argument("wilcoxon: all differences are zero");
  const std::size_t n = d.size();
  // Mean ranks of |d|, with the sizes of the tie groups.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return std::abs(d[a]) < std::abs(d[b]); });
  std::vector<double> rank(n);
  double tie_term = 0;
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i + 1;
    while (j < n && std::abs(d[order[j]]) == std::abs(d[order[i]])) ++j;
    const double mean_rank = 0.5 * double(i + 1 + j);  // ranks i+1 .. j
    for (std::size_t k = i; k < j; ++k) rank[order[k]] = mean_rank;
    const double t = double(j - i);
    tie_term += t * t * t - t;
    if (j - i > 1) r.ties = true;
    i = j;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (d[i] > 0) r.v += rank[i];
  const double nn = double(n);
  const double mean = nn * (nn + 1) / 4;
  const bool want_exact = o.exact == ExactMode::exact || (o.exact == ExactMode::automatic && n < 50);
  r.exact = want_exact && !r.ties && r.zeros == 0;
  if (r.exact) {
    r.z = std::numeric_limits<double>::quiet_NaN();
    const double upper = 1 - signed_rank_cdf(r.v - 1, r.n);  // P(V >= v)
    const double lower = signed_rank_cdf(r.v, r.n);          // P(V <= v)
    switch (o.alternative) {
      case Alternative::greater: r.p = upper; break;
      case Alternative::less: r.p = lower; break;
      case Alternative::two_sided: r.p = std::min(1.0, 2 * (r.v > mean ? upper : lower)); break;
    }
    return r;
  }
  const double sigma = std::sqrt(nn * (nn + 1) * (2 * nn + 1) / 24 - tie_term / 48);
  double z = r.v - mean;
  double correction = 0;
  if (o.correct) {
    switch (o.alternative) {
      case Alternative::two_sided: correction = z > 0 ? 0.5 : (z < 0 ? -0.5 : 0.0); break;
      case Alternative::greater: correction = 0.5; break;
      case Alternative::less: correction = -0.5; break;
    }
  }
  z = (z - correction) / sigma;
  r.z = z;
  const boost::math::normal_distribution<double> norm;
  const double lo = boost::math::cdf(norm, z), hi = boost::math::cdf(boost::math::complement(norm, z));
  switch (o.alternative) {
    case Alternative::greater: r.p = hi; break;
    case Alternative::less: r.p = lo; break;
    case Alternative::two_sided: r.p = std::min(1.0, 2 * std::min(lo, hi)); break;
  }
  return r;
}

}  // namespace

WilcoxonResult wilcoxon_signed_rank(const std::vector<double>& x, const std::vector<double>& y,
                                    const WilcoxonOptions& options) {
  if (x.size() != y.size()) throw std::invalid_argument("wilcoxon: paired samples of different lengths");
  std::vector<double> d(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) d[i] = x[i] - y[i] - options.mu;
  return signed_rank_of(std::move(d), options);
}

WilcoxonResult wilcoxon_signed_rank(const std::vector<double>& x, const WilcoxonOptions& options) {
  std::vector<double> d(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) d[i] = x[i] - options.mu;
  return signed_rank_of(std::move(d), options);
}

SignTest sign_test(const std::vector<double>& x, const std::vector<double>& y, Alternative alternative) {
  if (x.size() != y.size()) throw std::invalid_argument("sign test: paired samples of different lengths");
  SignTest s;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double d = x[i] - y[i];
    (d > 0 ? s.positive : d < 0 ? s.negative : s.zeros) += 1;
  }
  if (s.positive + s.negative == 0) throw std::invalid_argument("sign test: all differences are zero");
  s.p = binomial_test(unsigned(s.positive), unsigned(s.positive + s.negative), 0.5, alternative).p;
  return s;
}

}  // namespace ms
