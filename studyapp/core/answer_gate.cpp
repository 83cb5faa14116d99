// answer_gate: listening first, then (MUSHRA) every slider moved, then a complete answer.
#include "studyapp/core/answer_gate.hpp"

#include <algorithm>

namespace ms {

namespace {

std::string incomplete_wording(BlockType type) {
  switch (type) {
    case BlockType::magnitude: return "Type a number.";
    case BlockType::rating: return "Choose a point on every scale.";
    case BlockType::questionnaire: return "Answer every question that has choices.";
    case BlockType::adjust: return "Wait for the new sound.";
    case BlockType::instructions:
    case BlockType::bs1116:
    case BlockType::mushra: return "";
    default: return "Choose an answer.";
  }
}

}  // namespace

AnswerGate answer_gate(const Block& block, const TrialInputs& in) {
  const bool listening = block.type != BlockType::instructions && block.type != BlockType::questionnaire;
  if (listening && block.listen_all) {
    const auto heard = static_cast<std::size_t>(std::count(in.heard.begin(), in.heard.end(), true));
    if (heard < in.heard.size()) {
      if (in.heard.size() == 1) return {false, "Listen to the sound before answering."};
      return {false, "Listen to every sound before answering (" + std::to_string(heard) + " of " +
                         std::to_string(in.heard.size()) + " heard)."};
    }
    if (block.type == BlockType::mushra || block.type == BlockType::bs1116) {
      const auto left = static_cast<std::size_t>(std::count(in.moved.begin(), in.moved.end(), false));
      if (left > 0)
        return {false, "Rate every sound: move each slider at least once (" + std::to_string(left) +
                           (left == 1 ? " is" : " are") + " not rated yet)."};
    }
  }
  if (!in.complete) return {false, in.why_incomplete.empty() ? incomplete_wording(block.type) : in.why_incomplete};
  return {true, ""};
}

}  // namespace ms
