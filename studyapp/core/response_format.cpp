// check_answer: read_answer's verdict as a line; the A/B choice against the trial's stimuli.
#include "studyapp/core/response_format.hpp"

namespace ms {

std::string check_answer(const Block& block, const Trial& trial, const nlohmann::json& value) {
  try {
    read_answer(block, trial, value);
    return "";
  } catch (const AnswerError& e) {
    return e.what();
  }
}

std::string ab_chosen_stimulus(const nlohmann::json& stimuli, AbInterval chosen) {
  return stimuli.at(chosen == AbInterval::a ? 0 : 1).get<std::string>();
}

std::string ab_chosen_stimulus(const nlohmann::json& stimuli, const std::string& answer) {
  return ab_chosen_stimulus(stimuli, nlohmann::json(answer).get<ChoiceAnswer>().chosen);
}

bool abx_correct(const nlohmann::json& stimuli, AbInterval chosen) {
  return ab_chosen_stimulus(stimuli, chosen) == stimuli.at(2).get<std::string>();
}

bool abx_correct(const nlohmann::json& stimuli, const std::string& answer) {
  return abx_correct(stimuli, nlohmann::json(answer).get<ChoiceAnswer>().chosen);
}

}  // namespace ms
