// The check that an answer fits its trial before it is committed (the formats are answers.hpp's), and
// what an A/B choice means for its trial's stimuli.
#pragma once
#include <nlohmann/json.hpp>

#include <string>

#include "studyapp/core/answers.hpp"
#include "studyapp/core/protocol.hpp"
#include "studyapp/core/schedule.hpp"

namespace ms {

// "" when `value` is a valid answer to `trial` of `block`, else why not (one line).
std::string check_answer(const Block& block, const Trial& trial, const nlohmann::json& value);

// The stimulus an A/B choice picked from its trial's stored stimuli [A, B, (X)].
std::string ab_chosen_stimulus(const nlohmann::json& stimuli, AbInterval chosen);
std::string ab_chosen_stimulus(const nlohmann::json& stimuli, const std::string& answer);  // "A" | "B"

// ABX stores [A, B, X]: the answer is correct when the chosen one is X.
bool abx_correct(const nlohmann::json& stimuli, AbInterval chosen);
bool abx_correct(const nlohmann::json& stimuli, const std::string& answer);  // "A" | "B"

}  // namespace ms
