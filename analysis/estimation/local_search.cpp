#include "analysis/estimation/local_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace ms {

BoxedSearchResult nelder_mead_boxed(const std::function<double(const std::vector<double>&)>& f,
                                    std::vector<double> start, const BoxedSearchOptions& o) {
  const std::size_t n = start.size();
  if (o.lower.size() != n || o.upper.size() != n || o.step.size() != n)
    throw std::invalid_argument("nelder_mead_boxed: box and step must match the start's size");
  BoxedSearchResult r;
  auto clamp = [&](std::vector<double>& x) {
    for (std::size_t i = 0; i < n; ++i) x[i] = std::clamp(x[i], o.lower[i], o.upper[i]);
  };
  auto eval = [&](const std::vector<double>& x) {
    ++r.evaluations;
    const double v = f(x);
    return std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
  };
  clamp(start);
  std::vector<std::vector<double>> p(n + 1, start);
  std::vector<double> v(n + 1);
  for (std::size_t i = 0; i < n; ++i) {
    // Step inward when the start sits on the upper face.
    p[i + 1][i] += (start[i] + o.step[i] <= o.upper[i]) ? o.step[i] : -o.step[i];
    clamp(p[i + 1]);
  }
  for (std::size_t i = 0; i <= n; ++i) v[i] = eval(p[i]);
  std::vector<std::size_t> order(n + 1);
  auto point = [&](const std::vector<double>& c, const std::vector<double>& w, double t) {
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = c[i] + t * (w[i] - c[i]);
    clamp(x);
    return x;
  };
  while (r.evaluations < o.max_evaluations) {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
    const std::size_t best = order.front(), worst = order.back(), second = order[n - 1];
    double spread = 0.0;
    for (std::size_t k = 0; k <= n; ++k)
      for (std::size_t i = 0; i < n; ++i) spread = std::max(spread, std::abs(p[k][i] - p[best][i]));
    if (std::abs(v[worst] - v[best]) <= o.f_tolerance * (std::abs(v[best]) + 1e-300) && spread <= o.x_tolerance)
      break;
    ++r.iterations;
    std::vector<double> centroid(n, 0.0);
    for (std::size_t k = 0; k <= n; ++k)
      if (k != worst)
        for (std::size_t i = 0; i < n; ++i) centroid[i] += p[k][i] / double(n);
    const auto xr = point(centroid, p[worst], -1.0);
    const double fr = eval(xr);
    if (fr < v[best]) {
      const auto xe = point(centroid, p[worst], -2.0);
      const double fe = eval(xe);
      if (fe < fr) p[worst] = xe, v[worst] = fe;
      else p[worst] = xr, v[worst] = fr;
      continue;
    }
    if (fr < v[second]) {
      p[worst] = xr, v[worst] = fr;
      continue;
    }
    // Contract outside (towards the reflection) or inside (towards the worst vertex).
    const bool outside = fr < v[worst];
    const auto xc = point(centroid, outside ? xr : p[worst], 0.5);
    const double fc = eval(xc);
    if (fc < (outside ? fr : v[worst])) {
      p[worst] = xc, v[worst] = fc;
      continue;
    }
    for (std::size_t k = 0; k <= n; ++k)
      if (k != best) {
        p[k] = point(p[best], p[k], 0.5);
        v[k] = eval(p[k]);
      }
  }
  const std::size_t best = std::size_t(std::min_element(v.begin(), v.end()) - v.begin());
  r.x = p[best];
  r.value = v[best];
  return r;
}

}  // namespace ms
