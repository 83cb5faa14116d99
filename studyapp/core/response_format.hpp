// What an answer to each block type looks like (JSON, stored as the response value), and the check
// that an answer fits its trial before it is committed:
//   instructions   "ok"
//   ab             same_different: "same" | "different"; preference, abx, 2afc: "A" | "B"
//                  (abx: the one that is X); bipolar: integer -3..3 (B compared with A; with a
//                  block reference: positive when B is closer to the reference)
//   mushra         {"<stimulus>": 0..100, ...} for every stimulus of the trial (hidden reference too)
//   magnitude      number > 0 (the pair's dissimilarity, the modulus pair being 100); >= 0 with identical pairs
//   identify       one of the block's labels
//   rating         {"<attribute>": 1..points, ...} for every attribute
//   adjust         {"<key>": value within the slider's range, ...} for every slider
//   staircase      {"levels":[...], "correct":[...], "threshold": number|null}
//   questionnaire  {"<question id>": "text or option", ...}
#pragma once
#include <nlohmann/json.hpp>

#include <string>

#include "studyapp/core/protocol.hpp"
#include "studyapp/core/schedule.hpp"

namespace ms {

// "" when `value` is a valid answer to `trial` of `block`, else why not (one line).
std::string check_answer(const Block& block, const Trial& trial, const nlohmann::json& value);

// The stimulus an A/B answer "A" or "B" chose from its trial's stored stimuli [A, B, (X)].
std::string ab_chosen_stimulus(const nlohmann::json& stimuli, const std::string& answer);

// ABX stores [A, B, X]: the answer is correct when the chosen one is X.
bool abx_correct(const nlohmann::json& stimuli, const std::string& answer);

// Question id of a questionnaire item (written id, or "q<n>" 1-based).
std::string question_id(const Question& q, std::size_t index);

}  // namespace ms
