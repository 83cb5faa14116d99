#include "analysis/stats/quantile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ms {

double quantile(std::vector<double> x, double p) {
  if (x.empty()) throw std::invalid_argument("quantile of an empty sample");
  if (!(p >= 0 && p <= 1)) throw std::invalid_argument("quantile: p must lie in [0, 1]");
  for (double v : x)
    if (std::isnan(v)) throw std::invalid_argument("quantile: NaN in the sample");
  std::sort(x.begin(), x.end());
  const double h = double(x.size() - 1) * p;  // 0-based position
  const std::size_t lo = std::size_t(std::floor(h));
  const std::size_t hi = std::min(lo + 1, x.size() - 1);
  return x[lo] + (h - double(lo)) * (x[hi] - x[lo]);
}

double median(std::vector<double> x) { return quantile(std::move(x), 0.5); }

}  // namespace ms
