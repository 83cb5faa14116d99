#include "analysis/staircase.hpp"

#include <algorithm>
#include <cmath>

namespace ms {

StaircaseThreshold staircase_threshold(const std::vector<double>& levels, std::size_t last_k, bool log_scale) {
  StaircaseThreshold out;
  int direction = 0;  // +1 rising, -1 falling, 0 not yet moved
  for (std::size_t i = 1; i < levels.size(); ++i) {
    const double step = levels[i] - levels[i - 1];
    if (step == 0) continue;
    const int d = step > 0 ? 1 : -1;
    // The level before this step is where the track turned.
    if (direction != 0 && d != direction) {
      out.reversal_trials.push_back(i - 1);
      out.reversal_levels.push_back(levels[i - 1]);
    }
    direction = d;
  }
  const std::size_t n = out.reversal_levels.size();
  out.used = std::min(last_k, n);
  if (out.used == 0) return out;
  double sum = 0, sum2 = 0;
  for (std::size_t i = n - out.used; i < n; ++i) {
    const double v = log_scale ? std::log(out.reversal_levels[i]) : out.reversal_levels[i];
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / double(out.used);
  out.threshold = log_scale ? std::exp(mean) : mean;
  if (out.used >= 2) out.sd = std::sqrt(std::max(0.0, (sum2 - double(out.used) * mean * mean) / double(out.used - 1)));
  return out;
}

}  // namespace ms
