// Feedback on a training answer (`feedback: true`): whether the answer was right and what the right
// one was, for the block types that have one — same/different (the names of A and B), ABX (which of A
// and B is X), identification (the stimulus' `truth`, or the label that is its name) and MUSHRA (the
// hidden reference should be rated at least 90, BS.1534's post-screening bar). Other types (preference,
// bipolar, magnitude, rating, adjust) have no right answer: std::nullopt.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "studyapp/core/protocol.hpp"
#include "studyapp/core/schedule.hpp"

namespace ms {

struct TrainingFeedback {
  bool correct = false;
  std::string message;  // participant-facing, e.g. "Right: A and B were different."
};

std::optional<TrainingFeedback> training_feedback(const Protocol& protocol, const Block& block, const Trial& trial,
                                                  const nlohmann::json& answer);

// MUSHRA's participant-facing letter of the i-th rated sound (A..Z, then AA, AB, ...).
std::string mushra_letter(std::size_t index);

}  // namespace ms
