// One adaptive staircase track (Levitt 1971) run live: `down` correct answers in a row move the level
// by -step (harder), `up` wrong answers in a row move it by +step (easier). The protocol's `step` is
// the change that makes the difference EASIER to hear (for the 2002 a_v track: start 20 dB, step -1:
// a lower a_v prunes more modes). The track ends after `reversals` reversals or kMaxSteps steps.
// Each step plays the reference, then A and B: one of them the reference again, the other the
// comparison; which one is drawn from the session's seed, so a resumed track plays the same.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "studyapp/core/answers.hpp"

namespace ms {

class StaircaseTrack {
 public:
  static constexpr std::size_t kMaxSteps = 80;

  StaircaseTrack(double start, double step, int down, int up, int reversals);

  double level() const { return level_; }            // the level to present next
  void record(bool correct);                          // the answer at level()
  bool finished() const;
  std::size_t reversals() const { return reversal_count_; }
  const std::vector<double>& levels() const { return levels_; }    // presented, in order
  const std::vector<bool>& answers() const { return answers_; }
  // analysis/staircase's threshold of levels() with level() as the level after the last answer.
  std::optional<double> threshold() const;

 private:
  double level_, step_;
  int down_, up_, max_reversals_;
  int correct_run_ = 0, wrong_run_ = 0;
  int direction_ = 0;  // +1 easier, -1 harder, 0 before the first move
  std::size_t reversal_count_ = 0;
  std::vector<double> levels_;
  std::vector<bool> answers_;
};

// The interval (A or B) holding the comparison at `step` (0-based) of the track of trial `trial_index`
// of block `block_id`: a splitmix64 mix of the session's schedule seed and the position, the same with
// every standard library.
AbInterval staircase_comparison(std::uint64_t schedule_seed, const std::string& block_id, std::size_t trial_index,
                              std::size_t step);

// The listener names the interval that is the reference again: right when it is not the comparison.
bool staircase_correct(AbInterval comparison, AbInterval chosen);

}  // namespace ms
