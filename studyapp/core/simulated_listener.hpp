// The autopilot's listener: answers any trial from perceptual distances between the trial's stimuli
// (perceptual_distance.hpp) plus Gaussian decision noise, seeded, so a protocol can be piloted,
// demonstrated and tested without a person. Its answers are answers.hpp's typed answers, and its
// reaction times grow with how hard the decision was.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <string>

#include "studyapp/core/answers.hpp"
#include "studyapp/core/perceptual_distance.hpp"
#include "studyapp/core/protocol.hpp"
#include "studyapp/core/schedule.hpp"
#include "studyapp/core/stimulus_cache.hpp"

namespace ms {

struct SimulatedAnswer {
  Answer value;
  double rt_ms = 0.0;
  int plays = 1;
};

class SimulatedListener {
 public:
  // noise_db: standard deviation of the internal noise added to every distance (dB).
  SimulatedListener(StimulusCache& cache, std::uint64_t seed, double noise_db = 1.0);

  SimulatedAnswer answer(const Block& block, const Trial& trial);
  // One staircase step with the comparison at `level` in interval `comparison`: the interval the
  // listener names as the reference (the other one when the comparison is told apart).
  AbInterval staircase_choice(const StaircaseBlock& block, double level, AbInterval comparison);
  // One method-of-limits trial with the comparison at `level`: does the listener hear a change from
  // the reference? (the same rule as a same/different A/B trial)
  bool limits_different(const LimitsBlock& block, double level);
  // One step of a token series: does the listener hear the token of `comparison` modes differ from the
  // reference token of `reference` modes? (the same rule)
  bool tokens_different(const TokensBlock& block, int reference, int comparison);
  double distance_db(const std::string& a, const std::string& b);  // between named stimuli

 private:
  const PerceptualProfile& profile(const std::string& key, const Samples& samples);
  const PerceptualProfile& profile(const std::string& name);
  // `stimulus` with parameter-set key `key` at `value` (a level, a token's modes), rendered through the cache.
  const PerceptualProfile& profile_with(const std::string& stimulus, const std::string& key, double value);
  double noisy(double d);

  // One answer's standard-normal draws share one distribution (it hands out its values in pairs), so
  // the steps below take it by reference and draw in the order the seeded answers depend on.
  using UnitNormal = std::normal_distribution<double>;
  double reaction_ms(double distance_db, UnitNormal& unit);  // harder decisions take longer
  SimulatedAnswer answer_ab(AbMode mode, const Trial& trial, UnitNormal& unit);
  std::map<std::string, double> graded(const Trial& trial, const std::function<double(double)>& grade, double& hardest);
  SimulatedAnswer answer_mushra(const Trial& trial, UnitNormal& unit);
  SimulatedAnswer answer_bs1116(const Trial& trial, UnitNormal& unit);
  SimulatedAnswer answer_magnitude(const MagnitudeBlock& block, const Trial& trial, UnitNormal& unit);
  SimulatedAnswer answer_identify(const IdentifyBlock& block, const Trial& trial, UnitNormal& unit);
  SimulatedAnswer answer_rating(const RatingBlock& block, const Trial& trial, UnitNormal& unit);
  SimulatedAnswer answer_adjust(const AdjustBlock& block);
  SimulatedAnswer answer_changepoint(const Trial& trial, UnitNormal& unit);

  StimulusCache& cache_;
  std::mt19937_64 rng_;
  double noise_db_;
  std::map<std::string, PerceptualProfile> profiles_;  // by stimulus hash
};

}  // namespace ms
