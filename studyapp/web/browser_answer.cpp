// stored_answer / trial_inputs: the server's half of the window's answer gate.
#include "studyapp/web/browser_answer.hpp"

#include <algorithm>

#include "studyapp/core/magnitude_input.hpp"
#include "studyapp/core/response_format.hpp"
#include "studyapp/web/web_request.hpp"

namespace ms::web {

nlohmann::json stored_answer(const Block& block, const Presentation& p, const nlohmann::json& sent) {
  switch (block.type) {
    case BlockType::mushra:
    case BlockType::bs1116: {
      if (!sent.is_object()) throw Refusal(422, "the answer gives a grade per sound");
      nlohmann::json by_name = nlohmann::json::object();
      for (const auto& [id, score] : sent.items()) {
        const auto i = find_sound(p, id);
        if (!i || *i == 0) throw Refusal(422, "the answer rates a sound that is not one of this trial's rated sounds");
        by_name[p.sounds[*i].name] = score;
      }
      return by_name;
    }
    case BlockType::magnitude: {
      if (sent.is_number()) return sent;
      if (!sent.is_string()) throw Refusal(422, "Type a number.");
      const auto* spec = std::get_if<MagnitudeBlock>(&block.body);
      const MagnitudeEntry entry = spec ? read_magnitude(sent.get<std::string>(), *spec) : read_magnitude(sent.get<std::string>(), false);
      if (!entry.value) throw Refusal(422, entry.problem.empty() ? "Type a number." : entry.problem);
      return *entry.value;
    }
    case BlockType::adjust:
      // The stored values are those of the sound last made (and so heard), never others.
      if (sent != p.adjusted_values) throw Refusal(422, "the answer's values are not those of the sound last made");
      return sent;
    default: return sent;
  }
}

TrialInputs trial_inputs(const Block& block, const Trial& trial, const Presentation& p, const nlohmann::json& stored,
                         const nlohmann::json& moved_ids) {
  TrialInputs in;
  for (const PresentedSound& s : p.sounds) in.heard.push_back(s.heard);
  if (block.type == BlockType::mushra || block.type == BlockType::bs1116) {
    in.moved.assign(p.sounds.size() > 0 ? p.sounds.size() - 1 : 0, false);
    if (moved_ids.is_array())
      for (const auto& id : moved_ids)
        if (id.is_string())
          if (const auto i = find_sound(p, id.get<std::string>()); i && *i > 0) in.moved[*i - 1] = true;
  }
  if (block.type == BlockType::staircase) {
    in.complete = stored == "A" || stored == "B";
    return in;
  }
  if (block.type == BlockType::limits || block.type == BlockType::tokens) {
    in.complete = stored == "same" || stored == "different";
    return in;
  }
  in.why_incomplete = check_answer(block, trial, stored);
  in.complete = in.why_incomplete.empty();
  return in;
}

}  // namespace ms::web
