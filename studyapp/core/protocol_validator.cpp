// Protocol validation (see protocol_validator.hpp): collects every problem instead of stopping.
#include "studyapp/core/protocol_validator.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/stimulus_checks.hpp"
#include "synthesis/bounded_file.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/yaml_reader.hpp"

namespace ms {

namespace fs = std::filesystem;

namespace {

std::string at(const SourceLocation& w, const std::string& problem) {
  const std::string loc = format_location(w);
  return loc.empty() ? problem : loc + ": " + problem;
}

std::string suggest(const std::string& name, const std::vector<std::string>& candidates) {
  const std::string near = nearest_key(name, candidates);
  return near.empty() ? "" : " (did you mean '" + near + "'?)";
}

// Where the protocol wrote the override `key` of stimulus `s` (its name when not found).
SourceLocation override_location(const StimulusSource& s, const std::string& key) {
  for (std::size_t i = 0; i < s.overrides.size() && i < s.override_where.size(); ++i)
    if (s.overrides[i].rfind(key + "=", 0) == 0) return s.override_where[i];
  return s.where;
}

}  // namespace

namespace {

// The checks of one protocol, each problem one located line, all collected.
struct Checker {
  const Protocol& p;
  const ValidateOptions& options;
  Confinement confinement;
  std::vector<std::string> names;           // every stimulus name, for suggestions
  std::map<std::string, fs::path> loaded;   // parameter-set stimuli that load cleanly
  std::vector<std::string> problems;

  Checker(const Protocol& protocol, const ValidateOptions& o)
      : p(protocol), options(o), confinement(protocol_confinement(protocol, o)) {
    for (const auto& s : p.stimuli) names.push_back(s.name);
  }

  void ref(const StimulusRef& r, const std::string& what) {
    const auto& unparsed = p.unparsed_stimuli;  // reported by the parser already
    if (!p.find_stimulus(r.name) && std::find(unparsed.begin(), unparsed.end(), r.name) == unparsed.end())
      problems.push_back(at(r.where, what + "unknown stimulus '" + r.name + "'" + suggest(r.name, names)));
  }

  // Sliders and staircases set a parameter-set key live: it must load at the values they reach.
  void setting(const StimulusRef& stim, const std::string& key, double value, const SourceLocation& where,
               const std::string& who) {
    const auto it = loaded.find(stim.name);
    if (it == loaded.end()) return;
    auto overrides = p.find_stimulus(stim.name)->overrides;
    overrides.push_back(key + "=" + std::to_string(value));
    try {
      (void)load_paramset(it->second.string(), overrides, &confinement);
    } catch (const InputError& e) {
      problems.push_back(at(where, who + "'" + key + "' = " + std::to_string(value) + " on stimulus '" +
                                       stim.name + "': " + e.problem()));
    }
  }

  // Blocks that set a key of their stimulus live need a parameter set.
  void paramset_only(const StimulusRef& stim, const std::string& who) {
    const auto* s = p.find_stimulus(stim.name);
    if (s && s->kind != StimulusKind::paramset)
      problems.push_back(at(stim.where, who + "stimulus '" + s->name + "' is not a parameter set"));
  }

  // A token keeps the first K modes of the stimulus's pruning order: the stimulus needs a `prune:`, and
  // `from` may not exceed what it keeps (above that every token would be the same sound).
  void tokens(const TokensBlock& t, const std::string& who) {
    const auto it = loaded.find(t.stimulus.name);
    if (it == loaded.end()) return;
    const StimulusSource& s = *p.find_stimulus(t.stimulus.name);
    auto overrides = s.overrides;
    overrides.push_back(std::string(kTokenParameter) + "=" + std::to_string(t.from));
    try {
      const std::size_t before = load_paramset(it->second.string(), s.overrides, &confinement).modes_before_pruning;
      if (before == 0) {
        problems.push_back(at(t.stimulus.where, who + "stimulus '" + s.name + "' has no 'prune:' ordering its modes; "
                                                      "a token keeps its first K modes of that order (e.g. prune: "
                                                      "{method: naive})"));
        return;
      }
      const std::size_t kept = load_paramset(it->second.string(), overrides, &confinement).model.modes.size();
      if (kept < std::size_t(t.from))
        problems.push_back(at(t.from_where, who + "'from' is " + std::to_string(t.from) + " but stimulus '" + s.name +
                                                "' keeps only " + std::to_string(kept) + " modes after its pruning (" +
                                                std::to_string(before) + " before): tokens above " +
                                                std::to_string(kept) + " would all be the same sound"));
    } catch (const InputError& e) {
      problems.push_back(at(t.from_where, who + "'" + kTokenParameter + "' = " + std::to_string(t.from) +
                                              " on stimulus '" + s.name + "': " + e.problem()));
    }
  }

  void derived(const StimulusSource& s) {
    if (s.implicit) return;  // its reference is checked where the MUSHRA block names it
    if (!p.find_stimulus(s.derive_from.name)) {
      ref(s.derive_from, "stimulus '" + s.name + "' derives from ");
      return;
    }
    // Follow the derive chain; coming back to `s` is a cycle.
    std::set<std::string> seen{s.name};
    for (const StimulusSource* cur = p.find_stimulus(s.derive_from.name);
         cur && cur->kind == StimulusKind::derived; cur = p.find_stimulus(cur->derive_from.name)) {
      if (!seen.insert(cur->name).second) {
        problems.push_back(at(s.where, "stimulus '" + s.name + "': derive cycle through '" + cur->name + "'"));
        return;
      }
    }
  }

  // The stimuli a stimulus is made from: a derived one's source, a sequence's parts.
  std::vector<const StimulusSource*> sources_of(const StimulusSource& s) const {
    std::vector<const StimulusSource*> out;
    if (s.kind == StimulusKind::derived) out.push_back(p.find_stimulus(s.derive_from.name));
    for (const SequencePart& part : s.sequence) out.push_back(p.find_stimulus(part.stimulus.name));
    std::erase(out, nullptr);
    return out;
  }

  // A sequence's parts must exist and none may lead back to the sequence (through derived stimuli or
  // other sequences); each part is itself checked where it is defined (its file, its confinement).
  void sequence(const StimulusSource& s) {
    for (const SequencePart& part : s.sequence) ref(part.stimulus, "stimulus '" + s.name + "': sequence: ");
    std::set<std::string> seen;
    std::vector<std::pair<const StimulusSource*, std::string>> todo;  // stimulus, the part it came through
    for (const StimulusSource* part : sources_of(s)) todo.emplace_back(part, part->name);
    while (!todo.empty()) {
      const auto [cur, through] = todo.back();
      todo.pop_back();
      if (cur == &s) {
        problems.push_back(at(s.where, "stimulus '" + s.name + "': the sequence contains itself through '" + through + "'"));
        return;
      }
      if (!seen.insert(cur->name).second) continue;
      for (const StimulusSource* next : sources_of(*cur)) todo.emplace_back(next, through);
    }
  }

  void stimulus(const StimulusSource& s) {
    if (s.kind == StimulusKind::derived) return derived(s);
    if (s.kind == StimulusKind::sequence) return sequence(s);
    if (const std::string outside = confinement.problem(s.path, p.base_dir); !outside.empty()) {
      problems.push_back(at(s.path_where, "stimulus '" + s.name + "': " + outside));
      return;
    }
    const fs::path resolved = confinement.resolve(s.path, p.base_dir);
    // A written path can be unreadable in ways other than absence (a name too long, a loop of links).
    std::error_code status_error;
    if (!fs::exists(resolved, status_error)) {
      problems.push_back(at(s.path_where, "stimulus '" + s.name + "': file '" + s.path + "' " +
                                              (status_error ? "cannot be read: " + status_error.message()
                                                            : std::string("does not exist"))));
      return;
    }
    // The checks the stimulus cache makes when a session starts, so that check and start agree.
    try {
      if (s.kind == StimulusKind::paramset && options.load_paramsets) {
        const ParamSet set = load_paramset(resolved.string(), s.overrides, &confinement);
        check_paramset_stimulus(p, s, set);
        loaded[s.name] = resolved;
      } else if (s.kind == StimulusKind::file && options.load_paramsets) {
        (void)read_recording_stimulus(p, s, confinement);
      } else {
        ::close(open_bounded_file(resolved.string(), s.kind == StimulusKind::file ? kAudioFileLimit : kYamlFileLimit));
      }
    } catch (const InputError& e) {
      // Problems in overrides point at the stimulus in the protocol; others at the set's own file.
      if (e.where().file.rfind("--set ", 0) == 0)
        problems.push_back(at(override_location(s, e.where().file.substr(6)), "stimulus '" + s.name + "': " + e.problem()));
      else if (e.where().line == 0)
        problems.push_back(at(s.path_where, "stimulus '" + s.name + "': '" + s.path + "': " + e.problem()));
      else
        problems.push_back(e.what());
    }
  }

  // What each block type needs to have (and what its live settings must reach).
  void block_contents(const Block& b, const std::string& who) {
    auto empty = [&](const std::string& what) { problems.push_back(at(b.where, who + what)); };
    if (const auto* ins = std::get_if<InstructionsBlock>(&b.body); ins && ins->text.empty()) empty("no text");
    if (const auto* ab = std::get_if<AbBlock>(&b.body); ab && ab->pairs.empty()) empty("no pairs");
    if (const auto* m = std::get_if<MushraBlock>(&b.body)) {
      if (!m->reference) empty("MUSHRA needs a 'reference' (the hidden and open reference)");
      if (m->conditions.empty()) empty("no conditions");
    }
    if (const auto* t = std::get_if<Bs1116Block>(&b.body)) {
      if (t->conditions.empty()) empty("no conditions");
      for (const StimulusRef& c : t->conditions)
        if (c.name == t->reference.name)
          problems.push_back(at(c.where, who + "condition '" + c.name + "' is the reference, which every trial "
                                                "already plays as the hidden reference"));
    }
    if (const auto* g = std::get_if<MagnitudeBlock>(&b.body)) {
      if (g->all_pairs && g->stimuli.size() < 2) empty("'pairs: all' needs at least two stimuli");
      if (!g->all_pairs && g->pairs.empty()) empty("no pairs");
    }
    if (const auto* i = std::get_if<IdentifyBlock>(&b.body)) {
      if (i->stimuli.empty()) empty("no stimuli");
      if (i->labels.empty()) empty("identify needs 'labels' (the answer alternatives)");
    }
    if (const auto* r = std::get_if<RatingBlock>(&b.body)) {
      if (r->stimuli.empty()) empty("no stimuli");
      if (r->attributes.empty()) empty("no attributes");
    }
    if (const auto* a = std::get_if<AdjustBlock>(&b.body)) {
      if (a->sliders.empty()) empty("no sliders");
      paramset_only(a->paramset, who);
      for (const auto& sl : a->sliders)
        for (double v : {sl.min, sl.max}) setting(a->paramset, sl.key, v, sl.where, who);
    }
    if (const auto* s = std::get_if<StaircaseBlock>(&b.body)) {
      paramset_only(s->stimulus, who);
      setting(s->stimulus, s->parameter, s->start, s->parameter_where, who);
    }
    if (const auto* l = std::get_if<LimitsBlock>(&b.body)) {
      paramset_only(l->stimulus, who);
      setting(l->stimulus, l->parameter, l->start, l->parameter_where, who);
      if (l->floor) setting(l->stimulus, l->parameter, *l->floor, l->floor_where, who);
    }
    if (const auto* t = std::get_if<TokensBlock>(&b.body)) {
      paramset_only(t->stimulus, who);
      tokens(*t, who);
    }
    if (const auto* q = std::get_if<QuestionnaireBlock>(&b.body); q && q->questions.empty()) empty("no questions");
  }

  void block(const Block& b, std::map<std::string, const Block*>& ids) {
    const std::string who = "block '" + b.id + "': ";
    if (b.type == BlockType::unknown) {
      problems.push_back(at(b.type_where, "unknown block type '" + b.type_name + "'" +
                                              suggest(b.type_name, block_type_names())));
      return;
    }
    if (b.id_written) {
      const auto [it, fresh] = ids.emplace(b.id, &b);
      if (!fresh)
        problems.push_back(at(b.id_where, "duplicate block id '" + b.id + "' (first at " +
                                              format_location(it->second->id_where) + ")"));
    }
    for (const auto& r : b.referenced()) ref(r, who);
    block_contents(b, who);
  }

  // A shuffle group is one run of neighbouring blocks; it cannot be combined with a Latin square,
  // which already chooses the test blocks' order.
  void shuffle_groups() {
    std::map<std::string, std::size_t> last;  // group -> index of its latest block
    for (std::size_t i = 0; i < p.blocks.size(); ++i) {
      const Block& b = p.blocks[i];
      if (b.shuffle.empty()) continue;
      if (p.counterbalance == Counterbalance::latin_square) {
        problems.push_back(at(b.shuffle_where, "block '" + b.id + "': shuffle groups and counterbalance: "
                                               "latin_square both order blocks; use one of them"));
        return;
      }
      const auto seen = last.find(b.shuffle);
      if (seen != last.end() && seen->second + 1 != i)
        problems.push_back(at(b.shuffle_where, "block '" + b.id + "': shuffle group '" + b.shuffle +
                                               "' must be one run of neighbouring blocks (it was interrupted after "
                                               "block '" + p.blocks[seen->second].id + "')"));
      last[b.shuffle] = i;
    }
  }
};

}  // namespace

std::vector<std::string> validate_protocol(const Protocol& p, const ValidateOptions& options) {
  Checker check(p, options);
  for (const auto& s : p.stimuli) check.stimulus(s);
  std::map<std::string, const Block*> ids;
  for (const auto& b : p.blocks) check.block(b, ids);
  check.shuffle_groups();
  if (p.blocks.empty() && p.unparsed_blocks == 0) check.problems.push_back(at({p.file, 1, 1}, "the protocol has no blocks"));
  return std::move(check.problems);
}

Confinement protocol_confinement(const Protocol& p, const ValidateOptions& options) {
  if (options.allow_outside || p.allow_outside) return Confinement::anywhere();
  // The protocol's own folder and the project's stimuli/ folder.
  const fs::path base = canonical_or_self(p.base_dir.empty() ? "." : p.base_dir);
  std::vector<fs::path> roots{base};
  if (!options.stimuli_dir.empty()) {
    roots.push_back(options.stimuli_dir);
  } else {
    for (const fs::path& cand : {base / "stimuli", base.parent_path() / "stimuli"})
      if (std::error_code ec; fs::is_directory(cand, ec)) roots.push_back(cand);
  }
  return Confinement::within(roots, "the protocol's folder and the project's stimuli/ folder",
                             "use --allow-outside or allow_outside: true");
}

std::vector<std::string> protocol_warnings(const Protocol& p) {
  std::vector<std::string> out;
  for (const Block& b : p.blocks) {
    const auto* m = std::get_if<MushraBlock>(&b.body);
    if (!m || !m->auto_anchors || !m->reference) continue;
    for (const StimulusRef& c : m->conditions) {
      const StimulusSource* s = p.find_stimulus(c.name);
      if (!s || s->implicit || s->kind != StimulusKind::derived || s->derive_from.name != m->reference->name) continue;
      for (double hz : {3500.0, 7000.0})
        if (s->lowpass_hz == hz)
          out.push_back(at(c.where, "warning: block '" + b.id + "': condition '" + c.name + "' is the " +
                                        (hz == 3500.0 ? "3.5" : "7") + " kHz low-pass of '" + m->reference->name +
                                        "', which `anchors: auto` adds as '" + anchor_name(m->reference->name, hz) +
                                        "': the same sound is rated twice"));
    }
  }
  return out;
}

ProtocolCheck check_protocol_file(const std::string& path, const ValidateOptions& options) {
  ProtocolCheck c;
  try {
    c.protocol = load_protocol(path, &c.problems);
  } catch (const InputError& e) {
    c.problems.push_back(e.what());
    return c;
  }
  // The protocol as checked carries the permission it was checked with, for the stimulus cache.
  if (options.allow_outside) c.protocol->allow_outside = true;
  const auto more = validate_protocol(*c.protocol, options);
  c.problems.insert(c.problems.end(), more.begin(), more.end());
  c.warnings = protocol_warnings(*c.protocol);
  return c;
}

}  // namespace ms
