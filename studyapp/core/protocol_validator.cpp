// Protocol validation (see protocol_validator.hpp): collects every problem instead of stopping.
#include "studyapp/core/protocol_validator.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "studyapp/core/protocol_parser.hpp"
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

// True when `p` lies inside `root` (both canonical): compares whole path components.
bool inside(const fs::path& p, const fs::path& root) {
  auto pi = p.begin();
  for (auto ri = root.begin(); ri != root.end(); ++ri, ++pi) {
    if (ri->empty()) continue;  // trailing separator
    if (pi == p.end() || *pi != *ri) return false;
  }
  return true;
}

fs::path canonical_or_self(const fs::path& p) {
  std::error_code ec;
  auto c = fs::weakly_canonical(p, ec);
  return ec ? p.lexically_normal() : c;
}

}  // namespace

std::vector<std::string> validate_protocol(const Protocol& p, const ValidateOptions& options) {
  std::vector<std::string> problems;
  const SourceLocation top{p.file, 1, 1};

  std::vector<std::string> names;
  for (const auto& s : p.stimuli) names.push_back(s.name);
  auto check_ref = [&](const StimulusRef& r, const std::string& what) {
    if (!p.find_stimulus(r.name))
      problems.push_back(at(r.where, what + "unknown stimulus '" + r.name + "'" + suggest(r.name, names)));
  };

  // Folders a stimulus file may live in: the protocol's own and the project's stimuli/.
  const fs::path base = canonical_or_self(fs::absolute(p.base_dir.empty() ? "." : p.base_dir));
  std::vector<fs::path> roots{base};
  if (!options.stimuli_dir.empty()) {
    roots.push_back(canonical_or_self(fs::absolute(options.stimuli_dir)));
  } else {
    for (const fs::path& cand : {base / "stimuli", base.parent_path() / "stimuli"})
      if (fs::is_directory(cand)) roots.push_back(canonical_or_self(cand));
  }
  const bool allow_outside = options.allow_outside || p.allow_outside;
  std::map<std::string, fs::path> loaded;  // parameter-set stimuli that load cleanly

  // Sliders and staircases set a parameter-set key live: it must load at the values they reach.
  auto check_setting = [&](const StimulusRef& stim, const std::string& key, double value,
                           const SourceLocation& where, const std::string& who) {
    const auto it = loaded.find(stim.name);
    if (it == loaded.end()) return;
    auto overrides = p.find_stimulus(stim.name)->overrides;
    overrides.push_back(key + "=" + std::to_string(value));
    try {
      (void)load_paramset(it->second.string(), overrides);
    } catch (const InputError& e) {
      problems.push_back(at(where, who + "'" + key + "' = " + std::to_string(value) + " on stimulus '" +
                                       stim.name + "': " + e.problem()));
    }
  };

  for (const auto& s : p.stimuli) {
    if (s.kind == StimulusKind::derived) {
      if (s.implicit) continue;  // its reference is checked where the MUSHRA block names it
      if (!p.find_stimulus(s.derive_from.name)) {
        check_ref(s.derive_from, "stimulus '" + s.name + "' derives from ");
        continue;
      }
      // Follow the derive chain; coming back to `s` is a cycle.
      std::set<std::string> seen{s.name};
      for (const StimulusSource* cur = p.find_stimulus(s.derive_from.name);
           cur && cur->kind == StimulusKind::derived; cur = p.find_stimulus(cur->derive_from.name)) {
        if (!seen.insert(cur->name).second) {
          problems.push_back(at(s.where, "stimulus '" + s.name + "': derive cycle through '" + cur->name + "'"));
          break;
        }
      }
      continue;
    }
    const fs::path resolved = canonical_or_self(base / s.path);
    const bool ok_place = allow_outside || std::any_of(roots.begin(), roots.end(),
                                                       [&](const fs::path& r) { return inside(resolved, r); });
    if (!ok_place) {
      problems.push_back(at(s.path_where, "stimulus '" + s.name + "': path '" + s.path +
                                              "' is outside the protocol's folder and the project's stimuli/ "
                                              "folder (use --allow-outside or allow_outside: true)"));
      continue;
    }
    if (!fs::is_regular_file(resolved)) {
      problems.push_back(at(s.path_where, "stimulus '" + s.name + "': file '" + s.path + "' does not exist"));
      continue;
    }
    if (s.kind == StimulusKind::paramset && options.load_paramsets) {
      try {
        (void)load_paramset(resolved.string(), s.overrides);
        loaded[s.name] = resolved;
      } catch (const InputError& e) {
        // Problems in overrides point at the stimulus in the protocol; others at the set's own file.
        if (e.where().file.rfind("--set ", 0) == 0)
          problems.push_back(at(s.where, "stimulus '" + s.name + "': " + e.where().file.substr(6) + ": " + e.problem()));
        else
          problems.push_back(e.what());
      }
    }
  }

  std::map<std::string, const Block*> ids;
  for (const auto& b : p.blocks) {
    const std::string who = "block '" + b.id + "': ";
    if (b.type == BlockType::unknown) {
      problems.push_back(at(b.type_where, "unknown block type '" + b.type_name + "'" +
                                              suggest(b.type_name, block_type_names())));
      continue;
    }
    if (b.id_written) {
      const auto [it, fresh] = ids.emplace(b.id, &b);
      if (!fresh)
        problems.push_back(at(b.id_where, "duplicate block id '" + b.id + "' (first at " +
                                              format_location(it->second->id_where) + ")"));
    }
    for (const auto& r : b.referenced()) check_ref(r, who);
    auto empty = [&](const std::string& what) { problems.push_back(at(b.where, who + what)); };
    if (const auto* ins = std::get_if<InstructionsBlock>(&b.body); ins && ins->text.empty()) empty("no text");
    if (const auto* ab = std::get_if<AbBlock>(&b.body); ab && ab->pairs.empty()) empty("no pairs");
    if (const auto* m = std::get_if<MushraBlock>(&b.body)) {
      if (!m->reference) empty("MUSHRA needs a 'reference' (the hidden and open reference)");
      if (m->conditions.empty()) empty("no conditions");
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
      const auto* s = p.find_stimulus(a->paramset.name);
      if (s && s->kind != StimulusKind::paramset)
        problems.push_back(at(a->paramset.where, who + "stimulus '" + s->name + "' is not a parameter set"));
      for (const auto& sl : a->sliders)
        for (double v : {sl.min, sl.max}) check_setting(a->paramset, sl.key, v, sl.where, who);
    }
    if (const auto* s = std::get_if<StaircaseBlock>(&b.body)) {
      const auto* st = p.find_stimulus(s->stimulus.name);
      if (st && st->kind != StimulusKind::paramset)
        problems.push_back(at(s->stimulus.where, who + "stimulus '" + st->name + "' is not a parameter set"));
      check_setting(s->stimulus, s->parameter, s->start, s->parameter_where, who);
    }
    if (const auto* q = std::get_if<QuestionnaireBlock>(&b.body); q && q->questions.empty()) empty("no questions");
  }
  if (p.blocks.empty()) problems.push_back(at(top, "the protocol has no blocks"));
  return problems;
}

ProtocolCheck check_protocol_file(const std::string& path, const ValidateOptions& options) {
  ProtocolCheck c;
  try {
    c.protocol = load_protocol(path, &c.problems);
  } catch (const InputError& e) {
    c.problems.push_back(e.what());
    return c;
  }
  const auto more = validate_protocol(*c.protocol, options);
  c.problems.insert(c.problems.end(), more.begin(), more.end());
  return c;
}

}  // namespace ms
