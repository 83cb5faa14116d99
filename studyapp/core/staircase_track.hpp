// One adaptive staircase track (Levitt 1971) run live: `down` correct answers in a row move the level
// by -step (harder), `up` wrong answers in a row move it by +step (easier). The protocol's `step` is
// the change that makes the difference EASIER to hear (for the 2002 a_v track: start 20 dB, step -1:
// a lower a_v prunes more modes). The track ends after `reversals` reversals or kMaxSteps steps.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

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

}  // namespace ms
