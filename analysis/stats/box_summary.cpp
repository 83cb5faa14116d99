#include "analysis/stats/box_summary.hpp"

#include <algorithm>

#include "analysis/stats/quantile.hpp"

namespace ms {

BoxSummary box_summary(std::vector<double> x) {
  BoxSummary b;
  b.n = x.size();
  b.q1 = quantile(x, 0.25);  // throws for an empty x or a NaN
  b.median = quantile(x, 0.5);
  b.q3 = quantile(x, 0.75);
  std::sort(x.begin(), x.end());
  const double reach = 1.5 * (b.q3 - b.q1), low_fence = b.q1 - reach, high_fence = b.q3 + reach;
  b.lower_whisker = b.q1;
  b.upper_whisker = b.q3;
  for (double v : x) {
    if (v < low_fence || v > high_fence) {
      b.outliers.push_back(v);
      continue;
    }
    b.lower_whisker = std::min(b.lower_whisker, v);
    b.upper_whisker = std::max(b.upper_whisker, v);
  }
  return b;
}

}  // namespace ms
