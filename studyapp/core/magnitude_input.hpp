// What a participant typed as a magnitude estimate, read as a number: a decimal point or a decimal
// comma ("12,5"), surrounding blanks ignored; a refusal says why in the participant's words. 0 is a
// valid answer only where the block has identical pairs (no difference at all).
#pragma once
#include <optional>
#include <string>

#include "studyapp/core/protocol.hpp"

namespace ms {

struct MagnitudeEntry {
  std::optional<double> value;
  std::string problem;  // participant-facing; "" when value is set or nothing was typed
};

MagnitudeEntry read_magnitude(const std::string& text, bool zero_allowed);
// With the block's rules: 0 only where it has identical pairs; on its `scale` when it has one.
MagnitudeEntry read_magnitude(const std::string& text, const MagnitudeBlock& block);

}  // namespace ms
