// StaircaseTrack: the transformed up-down rule; see staircase_track.hpp.
#include "studyapp/core/staircase_track.hpp"

#include "analysis/stats/staircase.hpp"
#include "studyapp/core/schedule.hpp"

namespace ms {

StaircaseTrack::StaircaseTrack(double start, double step, int down, int up, int reversals)
    : level_(start), step_(step), down_(down), up_(up), max_reversals_(reversals) {}

void StaircaseTrack::record(bool correct) {
  levels_.push_back(level_);
  answers_.push_back(correct);
  int move = 0;  // +1 easier, -1 harder
  if (correct) {
    wrong_run_ = 0;
    if (++correct_run_ >= down_) {
      correct_run_ = 0;
      move = -1;
    }
  } else {
    correct_run_ = 0;
    if (++wrong_run_ >= up_) {
      wrong_run_ = 0;
      move = +1;
    }
  }
  if (move == 0) return;
  if (direction_ != 0 && move != direction_) ++reversal_count_;
  direction_ = move;
  level_ += move * step_;
}

bool StaircaseTrack::finished() const {
  return reversal_count_ >= static_cast<std::size_t>(max_reversals_) || levels_.size() >= kMaxSteps;
}

std::optional<double> StaircaseTrack::threshold() const {
  // The level the track moved to after the last answer counts too: its last reversal happened there.
  return staircase_threshold(levels_, level_).threshold;
}

AbInterval staircase_comparison(std::uint64_t schedule_seed, const std::string& block_id, std::size_t trial_index,
                              std::size_t step) {
  // participant_seed is the keyed splitmix64/FNV-1a mix; the key names the step.
  const std::uint64_t h =
      participant_seed(schedule_seed, "staircase/" + block_id + "/" + std::to_string(trial_index) + "/" + std::to_string(step));
  return (h >> 63) != 0 ? AbInterval::b : AbInterval::a;
}

bool staircase_correct(AbInterval comparison, AbInterval chosen) { return chosen != comparison; }

}  // namespace ms
