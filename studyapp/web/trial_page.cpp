// page_json: per block type what its view shows, in the window's terms; sounds only as {id, label}.
#include <cmath>

#include "studyapp/core/response_format.hpp"  // question_id
#include "studyapp/core/staircase_track.hpp"
#include "studyapp/web/trial_presentation.hpp"

namespace ms::web {

namespace {

nlohmann::json choices(const std::vector<std::pair<std::string, std::string>>& value_label) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [value, label] : value_label) list.push_back({{"value", value}, {"label", label}});
  return list;
}

void add_ab(nlohmann::json& page, const AbBlock& spec, const Trial& trial) {
  page["mode"] = to_string(spec.mode);
  const bool with_reference = spec.mode != AbMode::abx && trial.stimuli.size() > 2;
  page["with_reference"] = with_reference;
  switch (spec.mode) {
    case AbMode::same_different: page["choices"] = choices({{"same", "Same"}, {"different", "Different"}}); break;
    case AbMode::abx: page["choices"] = choices({{"A", "X is A"}, {"B", "X is B"}}); break;
    case AbMode::bipolar: page["bipolar"] = true; break;
    default: page["choices"] = choices({{"A", "A"}, {"B", "B"}}); break;
  }
}

void add_adjust(nlohmann::json& page, const AdjustBlock& spec, const Presentation& p, StimulusCache& cache) {
  nlohmann::json sliders = nlohmann::json::array();
  for (std::size_t i = 0; i < spec.sliders.size(); ++i) {
    const Slider& s = spec.sliders[i];
    sliders.push_back({{"key", s.key}, {"label", s.label.empty() ? "Slider " + std::to_string(i + 1) : s.label},
                       {"low", s.low}, {"high", s.high}, {"min", s.min}, {"max", s.max},
                       {"start", adjust_start_position(cache, spec.paramset.name, s)}, {"show_value", s.show_value}});
  }
  page["sliders"] = sliders;
  page["target"] = spec.target.has_value();
  page["adjusted"] = p.adjusted;
  page["values"] = p.adjusted_values;
}

}  // namespace

nlohmann::json page_json(Session& session, const Presentation& p, StimulusCache& cache) {
  const Trial& trial = session.current();
  const Block& block = session.current_block();
  nlohmann::json page{{"trial", p.trial}, {"step", p.step}, {"position", session.answered() + 1},
                      {"total", session.total()}, {"type", to_string(block.type)}, {"prompt", block.prompt},
                      {"training", block.training}, {"listen_all", block.listen_all}};
  nlohmann::json sounds = nlohmann::json::array();
  for (const PresentedSound& s : p.sounds) sounds.push_back({{"id", s.id}, {"label", s.label}});
  page["sounds"] = sounds;
  if (const auto* b = std::get_if<InstructionsBlock>(&block.body)) page["text"] = b->text;
  if (const auto* b = std::get_if<AbBlock>(&block.body)) add_ab(page, *b, trial);
  if (const auto* b = std::get_if<MagnitudeBlock>(&block.body)) {
    page["modulus_value"] = b->modulus_value;
    page["modulus_count"] = b->modulus ? 2 : 0;
    page["zero_allowed"] = b->identical_pairs && !b->scale;
    if (b->scale) page["scale"] = {{"min", b->scale->min}, {"max", b->scale->max}};
  }
  if (const auto* b = std::get_if<IdentifyBlock>(&block.body)) page["labels"] = b->labels;
  if (const auto* b = std::get_if<RatingBlock>(&block.body)) {
    nlohmann::json attributes = nlohmann::json::array();
    for (const RatingAttribute& a : b->attributes)
      attributes.push_back({{"name", a.name}, {"points", a.points}, {"low", a.low}, {"high", a.high}});
    page["attributes"] = attributes;
  }
  if (const auto* b = std::get_if<AdjustBlock>(&block.body)) add_adjust(page, *b, p, cache);
  if (const auto* b = std::get_if<StaircaseBlock>(&block.body)) {
    page["choices"] = choices({{"A", "A"}, {"B", "B"}});
    page["max_steps"] = StaircaseTrack::kMaxSteps;
    page["reversals"] = session.staircase().reversals();
    page["max_reversals"] = b->reversals;
  }
  if (std::holds_alternative<LimitsBlock>(block.body) || std::holds_alternative<TokensBlock>(block.body))
    page["choices"] = choices({{"same", "Same"}, {"different", "Different"}});
  if (const auto* b = std::get_if<TokensBlock>(&block.body)) page["comparisons"] = b->from - b->to;
  if (const auto* b = std::get_if<QuestionnaireBlock>(&block.body)) {
    nlohmann::json questions = nlohmann::json::array();
    for (std::size_t i = 0; i < b->questions.size(); ++i)
      questions.push_back({{"id", question_id(b->questions[i], i)}, {"text", b->questions[i].text},
                           {"options", b->questions[i].options}});
    page["questions"] = questions;
  }
  return page;
}

}  // namespace ms::web
