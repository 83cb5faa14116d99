#include "analysis/staircase.hpp"

#include <algorithm>
#include <cmath>

namespace ms {

std::size_t staircase_default_skip(std::size_t reversals) { return reversals > 4 ? 2 : 0; }

StaircaseThreshold staircase_threshold(const std::vector<double>& levels, std::optional<double> next_level,
                                       const StaircaseOptions& options) {
  std::vector<double> path = levels;
  if (next_level) path.push_back(*next_level);
  StaircaseThreshold out;
  int direction = 0;  // +1 rising, -1 falling, 0 not yet moved
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double step = path[i] - path[i - 1];
    if (step == 0) continue;
    const int d = step > 0 ? 1 : -1;
    // The level before this step is where the track turned.
    if (direction != 0 && d != direction) {
      out.reversal_trials.push_back(i - 1);
      out.reversal_levels.push_back(path[i - 1]);
    }
    direction = d;
  }
  const std::size_t n = out.reversal_levels.size();
  out.used = options.last_k ? std::min(*options.last_k, n) : n - staircase_default_skip(n);
  if (out.used == 0) return out;
  double sum = 0;
  for (std::size_t i = n - out.used; i < n; ++i)
    sum += options.log_scale ? std::log(out.reversal_levels[i]) : out.reversal_levels[i];
  const double mean = sum / double(out.used);
  out.threshold = options.log_scale ? std::exp(mean) : mean;
  if (out.used >= 2) {
    double ss = 0;  // two-pass: no cancellation for levels far from zero
    for (std::size_t i = n - out.used; i < n; ++i) {
      const double v = options.log_scale ? std::log(out.reversal_levels[i]) : out.reversal_levels[i];
      ss += (v - mean) * (v - mean);
    }
    out.sd = std::sqrt(ss / double(out.used - 1));
  }
  return out;
}

}  // namespace ms
