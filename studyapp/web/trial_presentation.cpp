// present: the sounds of the current trial under fresh opaque ids, in the order the window offers them.
#include "studyapp/web/trial_presentation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "studyapp/core/training_feedback.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/web/web_token.hpp"
#include "synthesis/csv.hpp"

namespace ms::web {

namespace {

PresentedSound sound_of(StimulusCache& cache, const std::string& name, const std::string& label,
                        std::vector<std::string> overrides = {}) {
  PresentedSound s;
  s.id = new_sound_id();
  s.label = label;
  s.name = name;
  s.stimulus = name;
  if (overrides.empty()) {
    cache.samples(name);  // on disk under its hash from here on
    s.hash = cache.hash(name);
  } else {
    cache.samples_with(name, overrides);
    s.hash = cache.hash_with(name, overrides);
  }
  s.overrides = std::move(overrides);
  return s;
}

double slider_value(const Slider& s, int position) { return s.min + (s.max - s.min) * position / 100.0; }

void present_staircase(Presentation& p, Session& session, const StaircaseBlock& block, StimulusCache& cache) {
  StaircaseTrack& track = session.staircase();
  p.step = track.levels().size();
  p.comparison_in_b = session.staircase_comparison() == AbInterval::b;  // drawn by the session: the same after a resume
  const std::string reference = block.reference ? block.reference->name : block.stimulus.name;
  const std::string level = override_text(block.parameter, track.level());
  PresentedSound comparison = sound_of(cache, block.stimulus.name, "", {level});
  comparison.name = block.stimulus.name + "@" + level;
  p.sounds.push_back(sound_of(cache, reference, "Reference"));
  p.sounds.push_back(p.comparison_in_b ? sound_of(cache, reference, "A") : comparison);
  p.sounds.push_back(p.comparison_in_b ? comparison : sound_of(cache, reference, "B"));
  p.sounds[1].label = "A";
  p.sounds[2].label = "B";
}

// The reference, then the stimulus at the series' level (the level is never sent).
void present_limits(Presentation& p, Session& session, const LimitsBlock& block, StimulusCache& cache) {
  DescendingSeries& series = session.limits();
  p.step = series.levels().size();
  const std::string level = override_text(block.parameter, series.level());
  p.sounds.push_back(sound_of(cache, block.reference ? block.reference->name : block.stimulus.name, "Reference"));
  p.sounds.push_back(sound_of(cache, block.stimulus.name, "Second sound", {level}));
  p.sounds.back().name = block.stimulus.name + "@" + level;
}

// The reference token, then the compared one: the stimulus with its first K modes (K never sent).
void present_tokens(Presentation& p, Session& session, const TokensBlock& block, StimulusCache& cache) {
  const TokenSeries& series = session.tokens();
  p.step = series.different().size();
  const std::string reference = override_text(kTokenParameter, series.reference());
  const std::string comparison = override_text(kTokenParameter, series.comparison());
  p.sounds.push_back(sound_of(cache, block.stimulus.name, "Reference", {reference}));
  p.sounds.back().name = block.stimulus.name + "@" + reference;
  p.sounds.push_back(sound_of(cache, block.stimulus.name, "Next sound", {comparison}));
  p.sounds.back().name = block.stimulus.name + "@" + comparison;
}

}  // namespace

std::string override_text(const std::string& key, double value) { return key + "=" + csv::number(value); }

std::optional<std::size_t> find_sound(const Presentation& p, const std::string& id) {
  for (std::size_t i = 0; i < p.sounds.size(); ++i)
    if (p.sounds[i].id == id) return i;
  return std::nullopt;
}

void render_adjust_variant(Presentation& p, const Block& block, StimulusCache& cache, const std::vector<int>& positions) {
  const auto& spec = std::get<AdjustBlock>(block.body);
  if (positions.size() != spec.sliders.size())
    throw std::invalid_argument("expected " + std::to_string(spec.sliders.size()) + " slider positions, got " +
                                std::to_string(positions.size()));
  std::vector<std::string> overrides;
  nlohmann::json values = nlohmann::json::object();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (positions[i] < 0 || positions[i] > 100) throw std::invalid_argument("a slider position must be 0..100");
    const double v = slider_value(spec.sliders[i], positions[i]);
    values[spec.sliders[i].key] = v;
    overrides.push_back(override_text(spec.sliders[i].key, v));
  }
  PresentedSound variant = sound_of(cache, spec.paramset.name, "Your sound", overrides);
  variant.detail_json = nlohmann::json{{"set", values}, {"hash", variant.hash}}.dump();
  p.sounds.at(p.adjusted) = std::move(variant);
  p.adjusted_values = std::move(values);
}

Presentation present(Session& session, StimulusCache& cache) {
  const Trial& trial = session.current();
  const Block& block = session.current_block();
  Presentation p;
  p.trial = session.current_index();
  const auto& names = trial.stimuli;
  switch (block.type) {
    case BlockType::ab: {
      const bool abx = std::get<AbBlock>(block.body).mode == AbMode::abx;
      for (std::size_t i = 0; i < names.size(); ++i)
        p.sounds.push_back(sound_of(cache, names[i], i == 0 ? "A" : i == 1 ? "B" : abx ? "X" : "Reference"));
      break;
    }
    case BlockType::mushra:
    case BlockType::bs1116:
      p.sounds.push_back(sound_of(cache, trial.reference, "Reference"));
      for (std::size_t i = 0; i < names.size(); ++i) p.sounds.push_back(sound_of(cache, names[i], mushra_letter(i)));
      break;
    case BlockType::magnitude: {
      const auto& spec = std::get<MagnitudeBlock>(block.body);
      if (spec.modulus) {
        p.sounds.push_back(sound_of(cache, (*spec.modulus)[0].name, "Reference pair 1"));
        p.sounds.push_back(sound_of(cache, (*spec.modulus)[1].name, "Reference pair 2"));
      }
      for (std::size_t i = 0; i < names.size(); ++i) p.sounds.push_back(sound_of(cache, names[i], i == 0 ? "A" : "B"));
      break;
    }
    case BlockType::identify:
    case BlockType::rating:
    case BlockType::changepoint:
      for (std::size_t i = 0; i < names.size(); ++i)
        p.sounds.push_back(sound_of(cache, names[i], names.size() == 1 ? "Sound" : "Sound " + std::to_string(i + 1)));
      break;
    case BlockType::adjust: {
      const auto& spec = std::get<AdjustBlock>(block.body);
      if (spec.target) p.sounds.push_back(sound_of(cache, spec.target->name, "Target"));
      p.adjusted = p.sounds.size();
      p.sounds.push_back(sound_of(cache, spec.paramset.name, "Your sound"));
      std::vector<int> start;
      for (const Slider& s : spec.sliders) start.push_back(adjust_start_position(cache, spec.paramset.name, s));
      render_adjust_variant(p, block, cache, start);
      break;
    }
    case BlockType::staircase: present_staircase(p, session, std::get<StaircaseBlock>(block.body), cache); break;
    case BlockType::limits: present_limits(p, session, std::get<LimitsBlock>(block.body), cache); break;
    case BlockType::tokens: present_tokens(p, session, std::get<TokensBlock>(block.body), cache); break;
    default: break;  // instructions, questionnaire: nothing to hear
  }
  p.page = page_json(session, p, cache);
  return p;
}

int adjust_start_position(const StimulusCache& cache, const std::string& stimulus, const Slider& s) {
  const auto v = cache.parameter_value(stimulus, s.key);
  if (!v || s.max == s.min) return 50;
  return std::clamp(static_cast<int>(std::lround(100.0 * (*v - s.min) / (s.max - s.min))), 0, 100);
}

}  // namespace ms::web
