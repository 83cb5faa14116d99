// One descending series of the method of limits run live (van den Doel et al. 2002, Experiment 1):
// the comparison starts at `start` (a_v = 20 dB, where no change is heard) and every trial plays the
// reference, then the comparison with the parameter at the series' level; the listener says "same" or
// "different". The level falls by |step| per trial; the series ends at the first "different", after the
// trial at `floor`, or after kMaxSteps trials. Levels are start + k * step (no summed rounding).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

namespace ms {

class DescendingSeries {
 public:
  static constexpr std::size_t kMaxSteps = 80;

  // step < 0 (the parser guarantees it); floor, when given, below start.
  DescendingSeries(double start, double step, std::optional<double> floor);

  double level() const;                                   // the level to present next
  void record(bool different);                            // the answer at level()
  bool finished() const;
  const std::vector<double>& levels() const { return levels_; }  // presented, in order
  const std::vector<bool>& different() const { return different_; }
  // analysis/method_of_limits: the last level answered "same" before the first "different".
  std::optional<double> threshold() const;

 private:
  double start_, step_;
  std::optional<double> floor_;
  std::vector<double> levels_;
  std::vector<bool> different_;
};

}  // namespace ms
