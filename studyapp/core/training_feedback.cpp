// training_feedback: the right answer derived from the trial's stimuli and the protocol's truth labels.
#include "studyapp/core/training_feedback.hpp"

#include <algorithm>

#include "studyapp/core/answers.hpp"

namespace ms {

namespace {

std::optional<std::string> identify_truth(const Protocol& p, const IdentifyBlock& b, const std::string& stimulus) {
  if (const StimulusSource* s = p.find_stimulus(stimulus))
    for (const auto& [attribute, label] : s->truth)
      if (std::find(b.labels.begin(), b.labels.end(), label) != b.labels.end()) return label;
  if (std::find(b.labels.begin(), b.labels.end(), stimulus) != b.labels.end()) return stimulus;
  return std::nullopt;
}

TrainingFeedback verdict(bool correct, const std::string& what) {
  return {correct, (correct ? "Right: " : "Not quite: ") + what};
}

}  // namespace

std::string mushra_letter(std::size_t index) {
  std::string s;
  for (std::size_t i = index + 1; i > 0; i = (i - 1) / 26) s.insert(s.begin(), char('A' + (i - 1) % 26));
  return s;
}

std::optional<TrainingFeedback> training_feedback(const Protocol& protocol, const Block& block, const Trial& trial,
                                                  const nlohmann::json& value) {
  Answer answer;
  try {
    answer = read_stored_answer(to_string(block.type), value);
  } catch (const AnswerError&) {
    return std::nullopt;  // not an answer of this block type: nothing to say about it
  }
  if (const auto* ab = std::get_if<AbBlock>(&block.body)) {
    if (trial.stimuli.size() < 2) return std::nullopt;
    if (const auto* sd = std::get_if<SameDifferentAnswer>(&answer); sd && ab->mode == AbMode::same_different) {
      const bool same = trial.stimuli[0] == trial.stimuli[1];
      return verdict(sd->different != same, same ? "A and B were the same sound." : "A and B were different sounds.");
    }
    if (const auto* choice = std::get_if<ChoiceAnswer>(&answer); choice && ab->mode == AbMode::abx &&
                                                                  trial.stimuli.size() == 3) {
      const AbInterval right = trial.stimuli[2] == trial.stimuli[0] ? AbInterval::a : AbInterval::b;
      return verdict(choice->chosen == right, "X was " + to_string(right) + ".");
    }
    return std::nullopt;
  }
  if (const auto* id = std::get_if<IdentifyBlock>(&block.body)) {
    const auto* given = std::get_if<IdentifyAnswer>(&answer);
    if (trial.stimuli.empty() || !given) return std::nullopt;
    const auto truth = identify_truth(protocol, *id, trial.stimuli[0]);
    if (!truth) return std::nullopt;
    return verdict(given->label == *truth, "the sound was " + *truth + ".");
  }
  if (const auto* mushra = std::get_if<MushraAnswer>(&answer)) {
    for (std::size_t i = 0; i < trial.stimuli.size(); ++i) {
      const auto rated = mushra->scores.find(trial.reference);
      if (trial.stimuli[i] != trial.reference || rated == mushra->scores.end()) continue;
      return verdict(rated->second >= 90.0, "sound " + mushra_letter(i) +
                                                " was the reference itself (hidden); it should be rated 90 or more.");
    }
  }
  return std::nullopt;
}

}  // namespace ms
