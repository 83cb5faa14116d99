// Threshold of an adaptive staircase track (Levitt 1971): the mean of the levels at the last k
// reversals, a reversal being a trial at which the direction of the level changes (steps of zero
// size do not change the direction). With log_scale the mean is geometric (levels in ratio units).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

namespace ms {

struct StaircaseThreshold {
  std::vector<std::size_t> reversal_trials;  // 0-based trial index of every reversal
  std::vector<double> reversal_levels;
  std::size_t used = 0;                      // reversals averaged (min(k, available))
  std::optional<double> threshold;           // none without reversals
  std::optional<double> sd;                  // of the used reversal levels (log units with log_scale), used >= 2
};

StaircaseThreshold staircase_threshold(const std::vector<double>& levels, std::size_t last_k, bool log_scale = false);

}  // namespace ms
