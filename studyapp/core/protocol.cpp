// Protocol model helpers: names of block types and modes, references of a block, lookups.
#include "studyapp/core/protocol.hpp"

#include <cmath>

namespace ms {

const std::vector<std::string>& block_type_names() {
  static const std::vector<std::string> names{"instructions", "ab",       "mushra",    "magnitude",
                                              "identify",     "rating",   "adjust",    "staircase",
                                              "questionnaire", "bs1116",   "limits",    "tokens",
                                              "changepoint"};
  return names;
}

std::string to_string(BlockType t) {
  const auto i = static_cast<std::size_t>(t);
  return i < block_type_names().size() ? block_type_names()[i] : "unknown";
}

std::string to_string(AbMode m) {
  switch (m) {
    case AbMode::same_different: return "same_different";
    case AbMode::preference: return "preference";
    case AbMode::abx: return "abx";
    case AbMode::two_afc: return "2afc";
    case AbMode::bipolar: return "bipolar";
  }
  return "?";
}

std::vector<StimulusRef> Block::referenced() const {
  std::vector<StimulusRef> out;
  auto add_pairs = [&](const std::vector<StimulusPair>& pairs) {
    for (const auto& p : pairs) out.insert(out.end(), p.begin(), p.end());
  };
  if (const auto* ab = std::get_if<AbBlock>(&body)) {
    add_pairs(ab->pairs);
    out.insert(out.end(), ab->references.begin(), ab->references.end());
  }
  if (const auto* m = std::get_if<MushraBlock>(&body)) {
    if (m->reference) out.push_back(*m->reference);
    out.insert(out.end(), m->conditions.begin(), m->conditions.end());
    if (!m->auto_anchors) out.insert(out.end(), m->anchors.begin(), m->anchors.end());
  }
  if (const auto* t = std::get_if<Bs1116Block>(&body)) {
    out.push_back(t->reference);
    out.insert(out.end(), t->conditions.begin(), t->conditions.end());
  }
  if (const auto* g = std::get_if<MagnitudeBlock>(&body)) {
    if (g->modulus) out.insert(out.end(), g->modulus->begin(), g->modulus->end());
    add_pairs(g->pairs);
    out.insert(out.end(), g->stimuli.begin(), g->stimuli.end());
  }
  if (const auto* i = std::get_if<IdentifyBlock>(&body)) out.insert(out.end(), i->stimuli.begin(), i->stimuli.end());
  if (const auto* r = std::get_if<RatingBlock>(&body)) out.insert(out.end(), r->stimuli.begin(), r->stimuli.end());
  if (const auto* a = std::get_if<AdjustBlock>(&body)) {
    out.push_back(a->paramset);
    if (a->target) out.push_back(*a->target);
  }
  if (const auto* s = std::get_if<StaircaseBlock>(&body)) {
    out.push_back(s->stimulus);
    if (s->reference) out.push_back(*s->reference);
  }
  if (const auto* l = std::get_if<LimitsBlock>(&body)) {
    out.push_back(l->stimulus);
    if (l->reference) out.push_back(*l->reference);
  }
  if (const auto* t = std::get_if<TokensBlock>(&body)) out.push_back(t->stimulus);
  if (const auto* c = std::get_if<ChangepointBlock>(&body))
    for (const auto& sweep : c->sweeps) out.insert(out.end(), sweep.begin(), sweep.end());
  return out;
}

const StimulusSource* Protocol::find_stimulus(const std::string& name) const {
  for (const auto& s : stimuli)
    if (s.name == name) return &s;
  return nullptr;
}

const Block* Protocol::find_block(const std::string& id) const {
  for (const auto& b : blocks)
    if (b.id == id) return &b;
  return nullptr;
}

std::string anchor_name(const std::string& reference, double hz) {
  return reference + "~lp" + std::to_string(std::llround(hz));
}

}  // namespace ms
