// Descending method of limits (van den Doel et al. 2002, Experiment 1): a parameter starts where no
// change is heard (a_v = 20 dB) and falls by one step per trial until the listener first hears a
// difference. The threshold is "the smallest value such that no change is detected": the level of the
// trial before the first "different" answer. A series that never changes is censored at its last
// level; one that is "different" from the first trial has no threshold (it lies above the start).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

struct LimitsThreshold {
  std::optional<double> threshold;        // none when the first trial was already "different"
  std::optional<std::size_t> first_different;  // 0-based trial index of the first "different"
  bool censored = false;                  // no "different" answer: threshold is the last level
};

// `levels` must fall strictly from trial to trial (throws std::invalid_argument naming the trial).
LimitsThreshold descending_limits_threshold(const std::vector<double>& levels, const std::vector<bool>& different);

// The series of a tidy table, one row per trial in presentation order, grouped by the `track`
// columns (in order of first appearance): the level of each trial and whether the answer was
// `different`. InputError at the cell for a level that is not a number or does not fall below the
// previous trial of its series; "no data rows".
struct LimitsColumns {
  std::string level, response, different = "different";
  std::vector<std::string> track;
};
struct LimitsSeries {
  std::string name;  // the track columns' values joined by '/', "" without track columns
  std::vector<double> levels;
  std::vector<bool> different;
};
std::vector<LimitsSeries> limits_series_from_table(const TidyCsv& table, const LimitsColumns& columns);

}  // namespace ms
