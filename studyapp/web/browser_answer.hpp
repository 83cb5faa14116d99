// An answer as a page sends it, turned into the answer the store keeps (response_format.hpp): MUSHRA
// scores keyed by opaque sound ids become scores keyed by stimulus names, a typed magnitude is read
// as the window reads it; and the answer gate's inputs as the server saw them (what was played).
#pragma once
#include <nlohmann/json.hpp>

#include "studyapp/core/answer_gate.hpp"
#include "studyapp/core/protocol.hpp"
#include "studyapp/core/schedule.hpp"
#include "studyapp/web/trial_presentation.hpp"

namespace ms::web {

// Throws Refusal 422 with the participant-facing reason when the sent answer cannot be an answer.
nlohmann::json stored_answer(const Block& block, const Presentation& p, const nlohmann::json& sent);

// heard: per sound a play or switch was logged; moved: MUSHRA sliders the page says were moved
// (`moved_ids`, opaque ids); complete and its reason from response_format's check of `stored`.
TrialInputs trial_inputs(const Block& block, const Trial& trial, const Presentation& p,
                         const nlohmann::json& stored, const nlohmann::json& moved_ids);

}  // namespace ms::web
