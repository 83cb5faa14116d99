// DescendingSeries: the descending rule; see descending_series.hpp.
#include "studyapp/core/descending_series.hpp"

#include <cmath>

#include "analysis/stats/method_of_limits.hpp"

namespace ms {

DescendingSeries::DescendingSeries(double start, double step, std::optional<double> floor)
    : start_(start), step_(step), floor_(floor) {}

double DescendingSeries::level() const { return start_ + static_cast<double>(levels_.size()) * step_; }

void DescendingSeries::record(bool different) {
  levels_.push_back(level());
  different_.push_back(different);
}

bool DescendingSeries::finished() const {
  if (!different_.empty() && different_.back()) return true;
  if (levels_.size() >= kMaxSteps) return true;
  // The floor itself is presented; a level below it (by more than rounding) is not.
  return floor_ && level() < *floor_ - 1e-9 * std::abs(step_);
}

std::optional<double> DescendingSeries::threshold() const {
  return descending_limits_threshold(levels_, different_).threshold;
}

}  // namespace ms
