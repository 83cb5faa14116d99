// training_feedback: the right answer derived from the trial's stimuli and the protocol's truth labels.
#include "studyapp/core/training_feedback.hpp"

#include <algorithm>

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
                                                  const nlohmann::json& answer) {
  if (const auto* ab = std::get_if<AbBlock>(&block.body)) {
    if (trial.stimuli.size() < 2 || !answer.is_string()) return std::nullopt;
    const std::string given = answer.get<std::string>();
    if (ab->mode == AbMode::same_different) {
      const bool same = trial.stimuli[0] == trial.stimuli[1];
      return verdict(given == (same ? "same" : "different"),
                     same ? "A and B were the same sound." : "A and B were different sounds.");
    }
    if (ab->mode == AbMode::abx && trial.stimuli.size() == 3) {
      const std::string right = trial.stimuli[2] == trial.stimuli[0] ? "A" : "B";
      return verdict(given == right, "X was " + right + ".");
    }
    return std::nullopt;
  }
  if (const auto* id = std::get_if<IdentifyBlock>(&block.body)) {
    if (trial.stimuli.empty() || !answer.is_string()) return std::nullopt;
    const auto truth = identify_truth(protocol, *id, trial.stimuli[0]);
    if (!truth) return std::nullopt;
    return verdict(answer.get<std::string>() == *truth, "the sound was " + *truth + ".");
  }
  if (block.type == BlockType::mushra) {
    if (!answer.is_object()) return std::nullopt;
    for (std::size_t i = 0; i < trial.stimuli.size(); ++i) {
      if (trial.stimuli[i] != trial.reference || !answer.contains(trial.reference)) continue;
      const double rating = answer[trial.reference].get<double>();
      return verdict(rating >= 90.0, "sound " + mushra_letter(i) +
                                         " was the reference itself (hidden); it should be rated 90 or more.");
    }
  }
  return std::nullopt;
}

}  // namespace ms
