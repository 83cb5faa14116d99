// SimulatedListener: one decision rule per block type, all driven by perceptual_distance_db plus
// Gaussian noise; see simulated_listener.hpp.
#include "studyapp/core/simulated_listener.hpp"

#include <algorithm>
#include <functional>
#include <cmath>


namespace ms {

namespace {

double clamp(double v, double lo, double hi) { return std::min(hi, std::max(lo, v)); }
double logistic(double x) { return 1.0 / (1.0 + std::exp(-x)); }

// The label a stimulus stands for: a label equal to its name or contained in it ("glass-plate").
std::string label_of(const std::string& stimulus, const std::vector<std::string>& labels) {
  for (const auto& l : labels)
    if (stimulus == l) return l;
  for (const auto& l : labels)
    if (stimulus.find(l) != std::string::npos) return l;
  return "";
}

// The first option of every multiple-choice question, "autopilot" for free text.
QuestionnaireAnswer questionnaire_answer(const QuestionnaireBlock& q) {
  QuestionnaireAnswer answers;
  for (std::size_t i = 0; i < q.questions.size(); ++i)
    answers.answers[question_id(q.questions[i], i)] = q.questions[i].options.empty() ? "autopilot" : q.questions[i].options[0];
  return answers;
}

std::string format_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

SimulatedListener::SimulatedListener(StimulusCache& cache, std::uint64_t seed, double noise_db)
    : cache_(cache), rng_(seed), noise_db_(noise_db) {}

const PerceptualProfile& SimulatedListener::profile(const std::string& key, const Samples& samples) {
  auto it = profiles_.find(key);
  if (it == profiles_.end()) it = profiles_.emplace(key, perceptual_profile(*samples, cache_.sample_rate_hz())).first;
  return it->second;
}

const PerceptualProfile& SimulatedListener::profile(const std::string& name) {
  return profile(cache_.hash(name), cache_.samples(name));
}

double SimulatedListener::distance_db(const std::string& a, const std::string& b) {
  return perceptual_distance_db(profile(a), profile(b));
}

double SimulatedListener::noisy(double d) {
  std::normal_distribution<double> n(0.0, noise_db_);
  return std::max(0.0, d + n(rng_));
}

const PerceptualProfile& SimulatedListener::profile_with(const std::string& stimulus, const std::string& key, double value) {
  const std::vector<std::string> set{key + "=" + format_number(value)};
  return profile(cache_.hash_with(stimulus, set), cache_.samples_with(stimulus, set));
}

AbInterval SimulatedListener::staircase_choice(const StaircaseBlock& block, double level, AbInterval comparison) {
  const PerceptualProfile& cmp = profile_with(block.stimulus.name, block.parameter, level);
  const PerceptualProfile ref = profile(block.reference ? block.reference->name : block.stimulus.name);
  const double d = perceptual_distance_db(ref, cmp);
  // 2-interval psychometric function: chance 50 %, 75 % correct at 1.5 dB.
  const double p = 0.5 + 0.5 * (1.0 - std::exp(-std::pow(d / 1.5, 2.0) * std::log(2.0)));
  const bool told_apart = std::uniform_real_distribution<double>(0.0, 1.0)(rng_) < p;
  return told_apart ? other(comparison) : comparison;
}

bool SimulatedListener::limits_different(const LimitsBlock& block, double level) {
  const PerceptualProfile& cmp = profile_with(block.stimulus.name, block.parameter, level);
  const PerceptualProfile ref = profile(block.reference ? block.reference->name : block.stimulus.name);
  return noisy(perceptual_distance_db(ref, cmp)) > 1.0;  // answer_ab's same/different criterion
}

bool SimulatedListener::tokens_different(const TokensBlock& block, int reference, int comparison) {
  const PerceptualProfile& ref = profile_with(block.stimulus.name, kTokenParameter, reference);
  const PerceptualProfile& cmp = profile_with(block.stimulus.name, kTokenParameter, comparison);
  return noisy(perceptual_distance_db(ref, cmp)) > 1.0;  // answer_ab's same/different criterion
}

// A change is marked where a sound differs from the one before it by more than the same/different
// criterion: the listener hears the sweep in order and notes each audible step.
SimulatedAnswer SimulatedListener::answer_changepoint(const Trial& trial, UnitNormal& unit) {
  ChangepointAnswer marks;
  double hardest = 1e9;
  for (std::size_t i = 1; i < trial.stimuli.size(); ++i) {
    const double d = noisy(distance_db(trial.stimuli[i - 1], trial.stimuli[i]));
    hardest = std::min(hardest, std::abs(d - 1.0));
    if (d > 1.0) marks.marks.push_back(i);
  }
  const auto n = trial.stimuli.size();
  return {marks, 1500.0 * double(n) + reaction_ms(hardest, unit), int(n)};
}

double SimulatedListener::reaction_ms(double distance_db, UnitNormal& unit) {
  // 600 ms plus up to 1.5 s for the smallest distances.
  return 600.0 + 1500.0 * std::exp(-distance_db / 3.0) + 100.0 * std::abs(unit(rng_));
}

SimulatedAnswer SimulatedListener::answer_ab(AbMode mode, const Trial& trial, UnitNormal& unit) {
  const auto& s = trial.stimuli;
  SimulatedAnswer a;
  a.plays = int(s.size());
  const double d = noisy(distance_db(s.at(0), s.at(1)));
  a.rt_ms = reaction_ms(d, unit);
  if (mode == AbMode::same_different) {
    a.value = SameDifferentAnswer{d > 1.0};
  } else if (mode == AbMode::abx) {
    const bool x_is_a = noisy(distance_db(s.at(0), s.at(2))) <= noisy(distance_db(s.at(1), s.at(2)));
    a.value = ChoiceAnswer{x_is_a ? AbInterval::a : AbInterval::b};
  } else if (mode == AbMode::bipolar && !trial.reference.empty()) {
    // B against A as a match to the reference: positive when B sounds closer to it.
    const double gain = noisy(distance_db(s.at(0), trial.reference)) - noisy(distance_db(s.at(1), trial.reference));
    a.value = BipolarAnswer{int(std::lround(clamp(gain / 2.0, -3.0, 3.0)))};
  } else if (mode == AbMode::bipolar) {
    a.value = BipolarAnswer{int(std::lround(clamp(-d / 2.0 + 0.5 * unit(rng_), -3.0, 3.0)))};
  } else {  // preference, 2afc: the brighter sound (higher loudness-weighted Bark centroid)
    const double ca = profile(s.at(0)).centroid_bark + 0.3 * unit(rng_);
    const double cb = profile(s.at(1)).centroid_bark + 0.3 * unit(rng_);
    a.value = ChoiceAnswer{ca >= cb ? AbInterval::a : AbInterval::b};
  }
  return a;
}

// Each sound's grade from its heard distance to the open reference; `hardest` the smallest distance.
std::map<std::string, double> SimulatedListener::graded(const Trial& trial, const std::function<double(double)>& grade,
                                                        double& hardest) {
  std::map<std::string, double> out;
  hardest = 1e9;
  for (const auto& name : trial.stimuli) {
    const double d = noisy(distance_db(trial.reference, name));
    hardest = std::min(hardest, d);
    out[name] = grade(d);
  }
  return out;
}

SimulatedAnswer SimulatedListener::answer_mushra(const Trial& trial, UnitNormal& unit) {
  double hardest = 0;
  const MushraAnswer scores{graded(trial, [](double d) { return std::round(clamp(100.0 * std::exp(-d / 6.0), 0.0, 100.0)); },
                                   hardest)};
  const auto n = trial.stimuli.size();
  return {scores, 4000.0 * double(n) + reaction_ms(hardest, unit), 2 * int(n) + 1};
}

// BS.1116: the impairment grade falls from 5.0 with the heard distance (the hidden reference, at
// distance 0 but for the listener's noise, near 5.0), to one decimal.
SimulatedAnswer SimulatedListener::answer_bs1116(const Trial& trial, UnitNormal& unit) {
  double hardest = 0;
  const Bs1116Answer grades{graded(trial, [](double d) {
    const double grade = 1.0 + 4.0 * std::exp(-std::max(0.0, d) / 6.0);
    return std::round(10.0 * clamp(grade, kBs1116GradeMin, kBs1116GradeMax)) / 10.0;
  }, hardest)};
  const auto n = trial.stimuli.size();
  return {grades, 4000.0 * double(n) + reaction_ms(hardest, unit), 2 * int(n) + 1};
}

SimulatedAnswer SimulatedListener::answer_magnitude(const MagnitudeBlock& m, const Trial& trial, UnitNormal& unit) {
  const auto& s = trial.stimuli;
  const double d_mod = m.modulus ? distance_db(m.modulus->at(0).name, m.modulus->at(1).name) : 3.0;
  const double d = noisy(distance_db(s.at(0), s.at(1)));
  const double ratio = (d + 0.5) / (d_mod + 0.5) * std::exp(0.1 * unit(rng_));
  // On a bounded scale (1 = identical) the ratio applies above its bottom: the modulus pair is at
  // modulus_value, an identical pair at min.
  const MagnitudeAnswer value{m.scale ? clamp(std::round(m.scale->min + (m.modulus_value - m.scale->min) * ratio),
                                              m.scale->min, m.scale->max)
                                      : std::max(1.0, std::round(m.modulus_value * ratio))};
  return {value, reaction_ms(d, unit) + 1500.0, int(s.size())};
}

SimulatedAnswer SimulatedListener::answer_identify(const IdentifyBlock& block, const Trial& trial, UnitNormal& unit) {
  // The label of the stimulus the sound seems closest to (itself included), among those whose
  // label is known; a sound with no known label gets a random one.
  const auto& labels = block.labels;
  std::string best;
  double best_d = 1e300;
  for (const auto& other : block.stimuli) {
    const std::string l = label_of(other.name, labels);
    if (l.empty()) continue;
    const double d = noisy(distance_db(trial.stimuli.at(0), other.name));
    if (d < best_d) best_d = d, best = l;
  }
  if (best.empty()) best = labels.at(std::size_t(std::uniform_int_distribution<std::size_t>(0, labels.size() - 1)(rng_)));
  return {IdentifyAnswer{best}, reaction_ms(best_d < 1e300 ? best_d : 0.0, unit), int(trial.stimuli.size())};
}

SimulatedAnswer SimulatedListener::answer_rating(const RatingBlock& block, const Trial& trial, UnitNormal& unit) {
  const PerceptualProfile& p = profile(trial.stimuli.at(0));
  RatingAnswer ratings;
  for (const auto& attr : block.attributes) {
    const bool temporal = attr.name.find("dur") != std::string::npos || attr.name.find("ring") != std::string::npos;
    const double x = temporal ? std::log(std::max(1e-3, p.decay_s) / 0.5) : (p.centroid_bark - 12.0) / 4.0;
    const double v = 1.0 + double(attr.points - 1) * logistic(x + 0.3 * unit(rng_));
    ratings.points[attr.name] = int(std::lround(clamp(v, 1.0, double(attr.points))));
  }
  return {ratings, reaction_ms(1.0, unit) + 1000.0, int(trial.stimuli.size())};
}

SimulatedAnswer SimulatedListener::answer_adjust(const AdjustBlock& adj) {
  // Tunes each slider in turn to the value (of 5 tried) that sounds closest to the block's target
  // (default: the stimulus as the protocol defines it), as a listener matching a target by ear would.
  const PerceptualProfile target = profile(adj.target ? adj.target->name : adj.paramset.name);
  AdjustAnswer values;
  int plays = 0;
  for (const auto& slider : adj.sliders) {
    double best_v = slider.min, best_d = 1e300;
    for (int k = 0; k < 5; ++k) {
      const double v = slider.min + (slider.max - slider.min) * (double(k) + 0.5) / 5.0;
      const std::vector<std::string> set{slider.key + "=" + format_number(v)};
      const double d = noisy(perceptual_distance_db(
          target, profile(cache_.hash_with(adj.paramset.name, set), cache_.samples_with(adj.paramset.name, set))));
      ++plays;
      if (d < best_d) best_d = d, best_v = v;
    }
    values.values[slider.key] = best_v;
  }
  return {values, 2500.0 * plays, plays};
}

SimulatedAnswer SimulatedListener::answer(const Block& block, const Trial& trial) {
  UnitNormal unit(0.0, 1.0);
  switch (block.type) {
    case BlockType::instructions:
      return {InstructionsAnswer{}, 3000.0, 0};
    case BlockType::ab:
      return answer_ab(std::get<AbBlock>(block.body).mode, trial, unit);
    case BlockType::mushra:
      return answer_mushra(trial, unit);
    case BlockType::bs1116:
      return answer_bs1116(trial, unit);
    case BlockType::magnitude:
      return answer_magnitude(std::get<MagnitudeBlock>(block.body), trial, unit);
    case BlockType::identify:
      return answer_identify(std::get<IdentifyBlock>(block.body), trial, unit);
    case BlockType::rating:
      return answer_rating(std::get<RatingBlock>(block.body), trial, unit);
    case BlockType::adjust:
      return answer_adjust(std::get<AdjustBlock>(block.body));
    case BlockType::questionnaire:
      return {questionnaire_answer(std::get<QuestionnaireBlock>(block.body)), 5000.0, 0};
    case BlockType::changepoint:
      return answer_changepoint(trial, unit);
    case BlockType::staircase:  // answered step by step through staircase_choice
    case BlockType::limits:     // answered step by step through limits_different
    case BlockType::tokens:     // answered step by step through tokens_different
    case BlockType::unknown:
      break;
  }
  SimulatedAnswer none;
  none.plays = int(trial.stimuli.size());
  return none;
}

}  // namespace ms
