#include "analysis/method_of_limits.hpp"

#include <stdexcept>

namespace ms {

LimitsThreshold descending_limits_threshold(const std::vector<double>& levels, const std::vector<bool>& different) {
  if (levels.size() != different.size()) throw std::invalid_argument("levels and answers differ in length");
  for (std::size_t i = 1; i < levels.size(); ++i)
    if (!(levels[i] < levels[i - 1]))
      throw std::invalid_argument("trial " + std::to_string(i + 1) + ": level " + std::to_string(levels[i]) +
                                  " does not fall below the previous one");
  LimitsThreshold t;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (!different[i]) continue;
    t.first_different = i;
    if (i > 0) t.threshold = levels[i - 1];
    return t;
  }
  if (!levels.empty()) {
    t.threshold = levels.back();
    t.censored = true;
  }
  return t;
}

}  // namespace ms
