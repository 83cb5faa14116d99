// Protocol YAML → Protocol (see protocol_parser.hpp). Semantic checks live in protocol_validator.
#include "studyapp/core/protocol_parser.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "studyapp/core/stimulus_sequence.hpp"
#include "synthesis/bounded_file.hpp"
#include "synthesis/yaml_reader.hpp"

namespace ms {

namespace {

std::string idx(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

bool flag(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  const std::string t = r.text(n, path);
  if (t == "true" || t == "yes" || t == "on") return true;
  if (t == "false" || t == "no" || t == "off") return false;
  r.fail(n, path, "expected true or false, got '" + t + "'");
}

int count(const YamlReader& r, const YAML::Node& n, const std::string& path, long long lo, long long hi) {
  const long long v = r.integer(n, path);
  if (v < lo || v > hi)
    r.fail(n, path, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " + n.Scalar());
  return static_cast<int>(v);
}

StimulusRef ref(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  return StimulusRef{r.text(n, path), r.where(n, path)};
}

std::vector<StimulusRef> refs(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  if (!n) return {};
  if (!n.IsSequence()) r.fail(n, path, "expected a list of stimulus names");
  std::vector<StimulusRef> out;
  for (std::size_t i = 0; i < n.size(); ++i) out.push_back(ref(r, n[i], idx(path, i)));
  return out;
}

StimulusPair pair(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  if (!n.IsSequence() || n.size() != 2) r.fail(n, path, "expected a pair [a, b] of stimulus names");
  return {ref(r, n[0], idx(path, 0)), ref(r, n[1], idx(path, 1))};
}

std::vector<StimulusPair> pairs(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  if (!n) return {};
  if (!n.IsSequence()) r.fail(n, path, "expected a list of pairs [[a, b], ...]");
  std::vector<StimulusPair> out;
  for (std::size_t i = 0; i < n.size(); ++i) out.push_back(pair(r, n[i], idx(path, i)));
  return out;
}

std::vector<std::string> texts(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  if (!n) return {};
  if (!n.IsSequence()) r.fail(n, path, "expected a list of text");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n.size(); ++i) out.push_back(r.text(n[i], idx(path, i)));
  return out;
}

// Flattens a YAML map into "a.b=value" overrides (values re-emitted as flow YAML).
void flatten(const YamlReader& r, const YAML::Node& n, const std::string& prefix, const std::string& path,
             std::vector<std::string>& out, std::vector<SourceLocation>& out_where) {
  if (!n.IsMap()) r.fail(n, path, "expected a map of parameter-set keys");
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string key = prefix.empty() ? it->first.Scalar() : prefix + "." + it->first.Scalar();
    if (it->second.IsMap()) {
      flatten(r, it->second, key, path + "." + it->first.Scalar(), out, out_where);
    } else {
      YAML::Emitter e;
      e << YAML::Flow << it->second;
      out.push_back(key + "=" + e.c_str());
      out_where.push_back(r.where(it->second, path + "." + it->first.Scalar()));
    }
  }
}

// A flat map name -> label ({shape: disc, material: metal}), in file order.
std::vector<std::pair<std::string, std::string>> labels_map(const YamlReader& r, const YAML::Node& n,
                                                            const std::string& path) {
  if (!n.IsMap() || n.size() == 0) r.fail(n, path, "expected a map name -> label, e.g. {material: metal}");
  std::vector<std::pair<std::string, std::string>> out;
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string name = r.text(it->first, path);
    if (name.empty()) r.fail(it->first, path, "empty name");
    out.emplace_back(name, r.text(it->second, path + "." + name));
  }
  return out;
}

// {sequence: [a, b, ...], onsets_s: [...], gains_db: [...]}: one onset (and optionally one gain) per
// named stimulus, the onsets rising strictly from >= 0 (stimulus_sequence.hpp).
std::vector<SequencePart> parse_sequence(const YamlReader& r, const YAML::Node& n, const std::string& path,
                                         const std::string& name) {
  const YAML::Node names = n["sequence"];
  if (!names.IsSequence() || names.size() == 0)
    r.fail(names, path + ".sequence", "expected a list of stimulus names, the strikes in the order they sound");
  std::vector<SequencePart> parts;
  for (std::size_t i = 0; i < names.size(); ++i) {
    parts.push_back(SequencePart{ref(r, names[i], idx(path + ".sequence", i))});
    if (parts.back().stimulus.name == name)
      r.fail(names[i], idx(path + ".sequence", i), "a sequence cannot contain itself");
  }
  // A list of one number per part, each checked by `value`.
  const auto per_part = [&](const char* key, const char* what, auto&& value) {
    const YAML::Node list = n[key];
    const std::string at = path + "." + key;
    if (!list.IsSequence()) r.fail(list, at, std::string("expected a list of ") + what + ", one per stimulus of 'sequence'");
    if (list.size() != parts.size())
      r.fail(list, at, "has " + std::to_string(list.size()) + " values but 'sequence' names " +
                           std::to_string(parts.size()) + " stimuli: give one per stimulus");
    for (std::size_t i = 0; i < list.size(); ++i) value(list[i], idx(at, i), i);
  };
  if (!n["onsets_s"]) r.fail(n, path, "a sequence needs 'onsets_s': when each stimulus starts, in seconds");
  per_part("onsets_s", "onsets in seconds", [&](const YAML::Node& v, const std::string& at, std::size_t i) {
    parts[i].onset_s = r.non_negative(v, at);
    if (parts[i].onset_s > kSequenceMaxS) r.fail(v, at, "absurd onset (more than 600 s)");
    if (i > 0 && parts[i].onset_s <= parts[i - 1].onset_s)
      r.fail(v, at, "onsets must rise: " + v.Scalar() + " s is not later than the onset before it");
  });
  if (n["gains_db"])
    per_part("gains_db", "gains in dB", [&](const YAML::Node& v, const std::string& at, std::size_t i) {
      parts[i].gain_db = r.number(v, at);
      if (parts[i].gain_db < kSequenceGainDbMin || parts[i].gain_db > kSequenceGainDbMax)
        r.fail(v, at, "a gain must lie between -120 and +40 dB, got " + v.Scalar());
    });
  return parts;
}

StimulusSource parse_stimulus(const YamlReader& r, const YAML::Node& key, const YAML::Node& n) {
  StimulusSource s;
  s.name = r.text(key, "stimuli");
  const std::string path = "stimuli." + s.name;
  s.where = r.where(key, path);
  if (!n.IsMap()) r.fail(n, path, "expected {paramset: ...}, {derive: ...}, {file: ...} or {sequence: ...}");
  const int kinds = int(bool(n["paramset"])) + int(bool(n["derive"])) + int(bool(n["file"])) + int(bool(n["sequence"]));
  if (kinds != 1) r.fail(n, path, "needs exactly one of 'paramset', 'derive', 'file' or 'sequence'");
  if (n["paramset"]) {
    r.check_keys(n, path, {"paramset", "set", "prune", "truth", "factors"});
    s.kind = StimulusKind::paramset;
    s.path = r.text(n["paramset"], path + ".paramset");
    s.path_where = r.where(n["paramset"], path + ".paramset");
    if (n["set"]) flatten(r, n["set"], "", path + ".set", s.overrides, s.override_where);
    if (n["prune"]) flatten(r, n["prune"], "prune", path + ".prune", s.overrides, s.override_where);
  } else if (n["derive"]) {
    r.check_keys(n, path, {"derive", "lowpass_hz", "truth", "factors"});
    s.kind = StimulusKind::derived;
    s.derive_from = ref(r, n["derive"], path + ".derive");
    if (!n["lowpass_hz"]) r.fail(n, path, "a derived stimulus needs 'lowpass_hz'");
    s.lowpass_hz = r.positive(n["lowpass_hz"], path + ".lowpass_hz");
  } else if (n["sequence"]) {
    r.check_keys(n, path, {"sequence", "onsets_s", "gains_db", "truth", "factors"});
    s.kind = StimulusKind::sequence;
    s.sequence = parse_sequence(r, n, path, s.name);
  } else {
    r.check_keys(n, path, {"file", "truth", "factors"});
    s.kind = StimulusKind::file;
    s.path = r.text(n["file"], path + ".file");
    s.path_where = r.where(n["file"], path + ".file");
  }
  if (n["truth"]) {
    if (n["truth"].IsScalar()) s.truth.emplace_back("", r.text(n["truth"], path + ".truth"));
    else s.truth = labels_map(r, n["truth"], path + ".truth");
  }
  if (n["factors"]) s.factors = labels_map(r, n["factors"], path + ".factors");
  return s;
}

// The value of a key the block type requires; a located error naming the block type when it is missing.
YAML::Node required(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b, const char* key) {
  if (!n[key]) r.fail(n, p, std::string("a '") + b.type_name + "' block needs '" + key + "'");
  return n[key];
}

InstructionsBlock parse_instructions(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "text"});
  return InstructionsBlock{r.text(required(r, n, p, b, "text"), p + ".text")};
}

AbBlock parse_ab(const YamlReader& r, const YAML::Node& n, const std::string& p) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "listen_all", "prompt", "feedback", "mode", "pairs"});
  AbBlock ab;
  if (n["mode"]) {
    const std::string m = r.text(n["mode"], p + ".mode");
    static const std::vector<std::string> modes{"same_different", "preference", "abx", "2afc", "bipolar"};
    const auto it = std::find(modes.begin(), modes.end(), m);
    if (it == modes.end()) {
      const std::string near = nearest_key(m, modes);
      r.fail(n["mode"], p + ".mode", "unknown mode '" + m + "'" +
                                         (near.empty() ? "" : " (did you mean '" + near + "'?)"));
    }
    ab.mode = static_cast<AbMode>(it - modes.begin());
  }
  // Pairs [A, B] or, for every pair alike, triples [A, B, REF] with a reference to compare against.
  const YAML::Node ps = n["pairs"];
  if (ps && !ps.IsSequence()) r.fail(ps, p + ".pairs", "expected a list of pairs [[a, b], ...]");
  for (std::size_t i = 0; ps && i < ps.size(); ++i) {
    const std::string ip = idx(p + ".pairs", i);
    const YAML::Node item = ps[i];
    const bool triple = item.IsSequence() && item.size() == 3;
    if (triple && ab.mode == AbMode::abx) r.fail(item, ip, "ABX plays X; a pair takes no reference");
    if (i > 0 && triple != !ab.references.empty())
      r.fail(item, ip, "write every pair of the block as [a, b] or every one as [a, b, reference]");
    if (!triple) {
      ab.pairs.push_back(pair(r, item, ip));
      continue;
    }
    ab.pairs.push_back({ref(r, item[0], idx(ip, 0)), ref(r, item[1], idx(ip, 1))});
    ab.references.push_back(ref(r, item[2], idx(ip, 2)));
  }
  return ab;
}

MushraBlock parse_mushra(const YamlReader& r, const YAML::Node& n, const std::string& p) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "listen_all", "reference",
                      "conditions", "anchors", "prompt", "feedback"});
  MushraBlock m;
  if (n["reference"]) m.reference = ref(r, n["reference"], p + ".reference");
  m.conditions = refs(r, n["conditions"], p + ".conditions");
  const YAML::Node a = n["anchors"];
  if (!a || (a.IsScalar() && a.Scalar() == "auto")) m.auto_anchors = true;  // BS.1534 default
  else if (a.IsScalar() && a.Scalar() == "none") m.auto_anchors = false;
  else m.anchors = refs(r, a, p + ".anchors");
  return m;
}

Bs1116Block parse_bs1116(const YamlReader& r, const YAML::Node& n, const std::string& p) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "listen_all",
                      "reference", "conditions", "prompt", "feedback"});
  if (!n["reference"]) r.fail(n, p, "a bs1116 block needs a 'reference' (the open and hidden reference)");
  Bs1116Block t;
  t.reference = ref(r, n["reference"], p + ".reference");
  t.conditions = refs(r, n["conditions"], p + ".conditions");
  return t;
}

MagnitudeBlock parse_magnitude(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "modulus", "pairs",
                      "stimuli", "listen_all", "prompt", "feedback", "modulus_value", "scale"});
  MagnitudeBlock g;
  g.modulus = pair(r, required(r, n, p, b, "modulus"), p + ".modulus");
  if (const YAML::Node sc = n["scale"]) {
    if (!sc.IsMap() || !sc["min"] || !sc["max"]) r.fail(sc, p + ".scale", "expected {min: 1, max: 10}");
    r.check_keys(sc, p + ".scale", {"min", "max"});
    MagnitudeBlock::Scale s{r.number(sc["min"], p + ".scale.min"), r.number(sc["max"], p + ".scale.max")};
    if (s.min < 0.0) r.fail(sc["min"], p + ".scale.min", "must not be negative");
    if (!(s.min < s.max)) r.fail(sc["max"], p + ".scale.max", "must be greater than min");
    g.scale = s;
    g.modulus_value = s.max;  // the standard pair is the most dissimilar one
  }
  if (n["modulus_value"]) {
    g.modulus_value = r.positive(n["modulus_value"], p + ".modulus_value");
    if (g.scale && (g.modulus_value < g.scale->min || g.modulus_value > g.scale->max))
      r.fail(n["modulus_value"], p + ".modulus_value", "must lie on the block's scale (" + n["scale"]["min"].Scalar() +
                                                          " to " + n["scale"]["max"].Scalar() + ")");
  }
  g.stimuli = refs(r, n["stimuli"], p + ".stimuli");
  const YAML::Node pr = n["pairs"];
  if (!pr || (pr.IsScalar() && pr.Scalar() == "all")) {
    g.all_pairs = true;
  } else if (pr.IsScalar() && pr.Scalar() == "all_with_identical") {
    g.all_pairs = g.identical_pairs = true;
  } else {
    g.pairs = pairs(r, pr, p + ".pairs");
  }
  return g;
}

IdentifyBlock parse_identify(const YamlReader& r, const YAML::Node& n, const std::string& p) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "stimuli", "labels",
                      "listen_all", "prompt", "feedback"});
  return IdentifyBlock{refs(r, n["stimuli"], p + ".stimuli"), texts(r, n["labels"], p + ".labels")};
}

RatingBlock parse_rating(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "listen_all", "stimuli",
                      "attributes", "prompt", "feedback"});
  RatingBlock rb;
  rb.stimuli = refs(r, n["stimuli"], p + ".stimuli");
  const YAML::Node at = required(r, n, p, b, "attributes");
  if (!at.IsSequence()) r.fail(at, p + ".attributes", "expected a list of {name, points, low, high}");
  for (std::size_t i = 0; i < at.size(); ++i) {
    const std::string ap = idx(p + ".attributes", i);
    r.check_keys(at[i], ap, {"name", "points", "low", "high"});
    RatingAttribute a;
    a.name = r.text(at[i]["name"], ap + ".name");
    if (at[i]["points"]) a.points = count(r, at[i]["points"], ap + ".points", 2, 101);
    if (at[i]["low"]) a.low = r.text(at[i]["low"], ap + ".low");
    if (at[i]["high"]) a.high = r.text(at[i]["high"], ap + ".high");
    rb.attributes.push_back(a);
  }
  return rb;
}

AdjustBlock parse_adjust(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "paramset", "sliders",
                      "target", "listen_all", "prompt", "feedback"});
  AdjustBlock ad;
  ad.paramset = ref(r, required(r, n, p, b, "paramset"), p + ".paramset");
  if (n["target"]) ad.target = ref(r, n["target"], p + ".target");
  const YAML::Node sl = n["sliders"];
  if (sl && !sl.IsSequence()) r.fail(sl, p + ".sliders", "expected a list of {key, min, max}");
  for (std::size_t i = 0; sl && i < sl.size(); ++i) {
    const std::string sp = idx(p + ".sliders", i);
    r.check_keys(sl[i], sp, {"key", "min", "max", "label", "low", "high", "show_value"});
    for (const char* key : {"key", "min", "max"})
      if (!sl[i][key]) r.fail(sl[i], sp, std::string("missing '") + key + "' (a slider is {key, min, max})");
    Slider s{r.text(sl[i]["key"], sp + ".key"), r.number(sl[i]["min"], sp + ".min"),
             r.number(sl[i]["max"], sp + ".max"), r.where(sl[i]["key"], sp + ".key")};
    if (!(s.min < s.max)) r.fail(sl[i]["max"], sp + ".max", "must be greater than min");
    if (sl[i]["label"]) s.label = r.text(sl[i]["label"], sp + ".label");
    if (sl[i]["low"]) s.low = r.text(sl[i]["low"], sp + ".low");
    if (sl[i]["high"]) s.high = r.text(sl[i]["high"], sp + ".high");
    if (sl[i]["show_value"]) s.show_value = flag(r, sl[i]["show_value"], sp + ".show_value");
    ad.sliders.push_back(s);
  }
  return ad;
}

// The keys a staircase and a series of limits share: a stimulus played at a level of `parameter`,
// against a reference, from `start` by `step`.
template <typename LevelBlock>
void read_level_series(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b, LevelBlock& s) {
  s.stimulus = ref(r, required(r, n, p, b, "stimulus"), p + ".stimulus");
  if (n["reference"]) s.reference = ref(r, n["reference"], p + ".reference");
  s.parameter = r.text(required(r, n, p, b, "parameter"), p + ".parameter");
  s.parameter_where = r.where(n["parameter"], p + ".parameter");
  s.start = r.number(required(r, n, p, b, "start"), p + ".start");
  s.step = r.number(required(r, n, p, b, "step"), p + ".step");
}

StaircaseBlock parse_staircase(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "stimulus",
                      "reference", "parameter", "start", "step", "down_up", "reversals",
                      "listen_all", "prompt", "feedback"});
  StaircaseBlock s;
  read_level_series(r, n, p, b, s);
  if (s.step == 0.0) r.fail(n["step"], p + ".step", "must not be 0");
  if (const YAML::Node du = n["down_up"]) {
    if (!du.IsSequence() || du.size() != 2) r.fail(du, p + ".down_up", "expected [down, up], e.g. [2, 1]");
    s.down = count(r, du[0], p + ".down_up[0]", 1, 10);
    s.up = count(r, du[1], p + ".down_up[1]", 1, 10);
  }
  if (n["reversals"]) s.reversals = count(r, n["reversals"], p + ".reversals", 1, 100);
  return s;
}

LimitsBlock parse_limits(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "stimulus",
                      "reference", "parameter", "start", "step", "floor", "listen_all", "prompt"});
  LimitsBlock l;
  read_level_series(r, n, p, b, l);
  if (!(l.step < 0.0)) r.fail(n["step"], p + ".step", "a descending series needs a negative step (e.g. -1), got " + n["step"].Scalar());
  if (n["floor"]) {
    l.floor = r.number(n["floor"], p + ".floor");
    l.floor_where = r.where(n["floor"], p + ".floor");
    if (!(*l.floor < l.start)) r.fail(n["floor"], p + ".floor", "must lie below start (the series descends)");
  }
  return l;
}

TokensBlock parse_tokens(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "stimulus",
                      "from", "to", "listen_all", "prompt"});
  TokensBlock t;
  t.stimulus = ref(r, required(r, n, p, b, "stimulus"), p + ".stimulus");
  t.from = count(r, required(r, n, p, b, "from"), p + ".from", 2, 100000);
  t.from_where = r.where(n["from"], p + ".from");
  if (n["to"]) {
    t.to = count(r, n["to"], p + ".to", 1, 100000);
    t.to_where = r.where(n["to"], p + ".to");
    if (t.to >= t.from) r.fail(n["to"], p + ".to", "must lie below from (" + n["from"].Scalar() + "): the tokens lose modes");
  }
  return t;
}

// Sweeps share `values`, one per sound in playing order, strictly rising or strictly falling.
ChangepointBlock parse_changepoint(const YamlReader& r, const YAML::Node& n, const std::string& p, const Block& b) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "repeats", "parameter",
                      "values", "sweeps", "listen_all", "prompt"});
  ChangepointBlock c;
  c.parameter = r.text(required(r, n, p, b, "parameter"), p + ".parameter");
  if (c.parameter.empty()) r.fail(n["parameter"], p + ".parameter", "names the swept quantity (e.g. Q); got nothing");
  const YAML::Node v = required(r, n, p, b, "values");
  c.values = r.numbers(v, p + ".values");
  c.values_where = r.where(v, p + ".values");
  if (c.values.size() < 3)
    r.fail(v, p + ".values", "a sweep needs at least 3 sounds (a change point lies between neighbours), got " +
                                 std::to_string(c.values.size()));
  const bool rising = c.values[1] > c.values[0];
  for (std::size_t i = 1; i < c.values.size(); ++i)
    if (rising ? !(c.values[i] > c.values[i - 1]) : !(c.values[i] < c.values[i - 1]))
      r.fail(v[i], idx(p + ".values", i), std::string("the values must ") + (rising ? "rise" : "fall") +
                                              " all the way (a sweep is monotone): " + v[i].Scalar() + " after " +
                                              v[i - 1].Scalar());
  const YAML::Node sw = required(r, n, p, b, "sweeps");
  if (!sw.IsSequence() || sw.size() == 0) r.fail(sw, p + ".sweeps", "expected a list of sweeps [[sound, ...], ...]");
  for (std::size_t i = 0; i < sw.size(); ++i) {
    const std::string sp = idx(p + ".sweeps", i);
    std::vector<StimulusRef> sweep = refs(r, sw[i], sp);
    if (sweep.size() != c.values.size())
      r.fail(sw[i], sp, "has " + std::to_string(sweep.size()) + " sounds but 'values' has " +
                            std::to_string(c.values.size()) + " (one value per sound, in playing order)");
    for (std::size_t k = 1; k < sweep.size(); ++k)
      for (std::size_t j = 0; j < k; ++j)
        if (sweep[k].name == sweep[j].name) r.fail(sw[i][k], idx(sp, k), "plays '" + sweep[k].name + "' twice");
    c.sweeps.push_back(std::move(sweep));
  }
  return c;
}

QuestionnaireBlock parse_questionnaire(const YamlReader& r, const YAML::Node& n, const std::string& p) {
  r.check_keys(n, p, {"type", "id", "randomize", "training", "shuffle", "break_after", "questions", "prompt"});
  QuestionnaireBlock q;
  const YAML::Node qs = n["questions"];
  if (qs && !qs.IsSequence()) r.fail(qs, p + ".questions", "expected a list of questions");
  for (std::size_t i = 0; qs && i < qs.size(); ++i) {
    const std::string qp = idx(p + ".questions", i);
    Question question;
    question.id = "q" + std::to_string(i + 1);
    if (qs[i].IsScalar()) {
      question.text = r.text(qs[i], qp);
    } else {
      r.check_keys(qs[i], qp, {"id", "text", "options"});
      if (qs[i]["id"]) question.id = r.text(qs[i]["id"], qp + ".id");
      if (!qs[i]["text"]) r.fail(qs[i], qp + ".text", "missing: a question needs its text");
      question.text = r.text(qs[i]["text"], qp + ".text");
      question.options = texts(r, qs[i]["options"], qp + ".options");
    }
    q.questions.push_back(question);
  }
  return q;
}

BlockBody parse_body(const YamlReader& r, const YAML::Node& n, const std::string& p, Block& b) {
  switch (b.type) {
    case BlockType::instructions: return parse_instructions(r, n, p, b);
    case BlockType::ab: return parse_ab(r, n, p);
    case BlockType::mushra: return parse_mushra(r, n, p);
    case BlockType::magnitude: return parse_magnitude(r, n, p, b);
    case BlockType::identify: return parse_identify(r, n, p);
    case BlockType::rating: return parse_rating(r, n, p, b);
    case BlockType::adjust: return parse_adjust(r, n, p, b);
    case BlockType::staircase: return parse_staircase(r, n, p, b);
    case BlockType::questionnaire: return parse_questionnaire(r, n, p);
    case BlockType::bs1116: return parse_bs1116(r, n, p);
    case BlockType::limits: return parse_limits(r, n, p, b);
    case BlockType::tokens: return parse_tokens(r, n, p, b);
    case BlockType::changepoint: return parse_changepoint(r, n, p, b);
    case BlockType::unknown: break;
  }
  return std::monostate{};
}

Block parse_block(const YamlReader& r, const YAML::Node& n, std::size_t index) {
  const std::string p = idx("blocks", index);
  if (!n.IsMap()) r.fail(n, p, "expected a block map {type: ..., ...}");
  Block b;
  b.where = r.where(n, p);
  if (!n["type"]) r.fail(n, p, "a block needs a 'type'");
  b.type_name = r.text(n["type"], p + ".type");
  b.type_where = r.where(n["type"], p + ".type");
  const auto& names = block_type_names();
  const auto it = std::find(names.begin(), names.end(), b.type_name);
  b.type = it == names.end() ? BlockType::unknown : static_cast<BlockType>(it - names.begin());
  b.id = (b.type == BlockType::unknown ? std::string("block") : b.type_name) + "-" + std::to_string(index + 1);
  if (n["id"]) {
    b.id = r.text(n["id"], p + ".id");
    b.id_written = true;
    b.id_where = r.where(n["id"], p + ".id");
  }
  if (n["randomize"]) b.randomize = flag(r, n["randomize"], p + ".randomize");
  if (n["training"]) b.training = flag(r, n["training"], p + ".training");
  if (n["shuffle"]) {
    b.shuffle = r.text(n["shuffle"], p + ".shuffle");
    b.shuffle_where = r.where(n["shuffle"], p + ".shuffle");
  }
  if (n["break_after"]) b.break_after = count(r, n["break_after"], p + ".break_after", 0, 100000);
  if (n["listen_all"]) b.listen_all = flag(r, n["listen_all"], p + ".listen_all");
  if (n["prompt"]) b.prompt = r.text(n["prompt"], p + ".prompt");
  if (n["feedback"]) b.feedback = flag(r, n["feedback"], p + ".feedback");
  if (n["repeats"]) b.repeats = count(r, n["repeats"], p + ".repeats", 1, 1000);
  if (b.type != BlockType::unknown) b.body = parse_body(r, n, p, b);
  return b;
}

}  // namespace

Protocol parse_protocol(const std::string& yaml_text, const std::string& file_for_errors,
                        const std::string& base_dir, std::vector<std::string>* problems) {
  const YamlReader r(file_for_errors);
  const YAML::Node root = r.load(yaml_text);
  Protocol pr;
  pr.file = file_for_errors;
  pr.base_dir = base_dir;
  if (!root.IsMap()) r.fail(root, "", "a protocol is a map with study, title, stimuli and blocks");
  r.check_keys(root, "", {"study", "title", "sample_rate", "seed", "counterbalance", "allow_outside",
                          "export_personal", "stimuli", "blocks"});
  if (!root["study"]) r.fail(root, "", "missing 'study' (the study id)");
  pr.study = r.identifier(root["study"], "study");
  if (root["title"]) pr.title = r.text(root["title"], "title");
  if (root["sample_rate"]) pr.sample_rate_hz = r.positive(root["sample_rate"], "sample_rate");
  if (root["seed"]) {
    const long long s = r.integer(root["seed"], "seed");
    if (s < 0) r.fail(root["seed"], "seed", "must not be negative");
    pr.seed = static_cast<std::uint64_t>(s);
  }
  if (root["counterbalance"]) {
    const std::string c = r.text(root["counterbalance"], "counterbalance");
    if (c == "latin_square") pr.counterbalance = Counterbalance::latin_square;
    else if (c != "none") r.fail(root["counterbalance"], "counterbalance", "expected none or latin_square, got '" + c + "'");
  }
  if (root["allow_outside"]) pr.allow_outside = flag(r, root["allow_outside"], "allow_outside");
  if (root["export_personal"]) pr.export_personal = flag(r, root["export_personal"], "export_personal");

  // A bad stimulus or block is collected (with `problems`) so one run reports all of them.
  auto guarded = [&](auto&& fn) {
    if (!problems) return fn();
    try {
      fn();
    } catch (const InputError& e) {
      problems->push_back(e.what());
    }
  };
  const YAML::Node st = root["stimuli"];
  if (st && !st.IsMap()) r.fail(st, "stimuli", "expected a map name -> source");
  for (auto it = st.begin(); st && it != st.end(); ++it) {
    const std::size_t before = problems ? problems->size() : 0;
    guarded([&] { pr.stimuli.push_back(parse_stimulus(r, it->first, it->second)); });
    if (problems && problems->size() > before) pr.unparsed_stimuli.push_back(it->first.Scalar());
  }
  const YAML::Node bl = root["blocks"];
  if (bl && !bl.IsSequence()) r.fail(bl, "blocks", "expected a list of blocks");
  for (std::size_t i = 0; bl && i < bl.size(); ++i) {
    const std::size_t before = problems ? problems->size() : 0;
    guarded([&] { pr.blocks.push_back(parse_block(r, bl[i], i)); });
    if (problems && problems->size() > before) ++pr.unparsed_blocks;
  }

  // `anchors: auto`: the BS.1534 3.5 kHz and 7 kHz low-passed references, as implicit stimuli.
  for (auto& b : pr.blocks) {
    auto* m = std::get_if<MushraBlock>(&b.body);
    if (!m || !m->auto_anchors || !m->reference) continue;
    for (double hz : {3500.0, 7000.0}) {
      const std::string name = anchor_name(m->reference->name, hz);
      m->anchors.push_back(StimulusRef{name, m->reference->where});
      if (pr.find_stimulus(name)) continue;
      StimulusSource s;
      s.name = name;
      s.kind = StimulusKind::derived;
      s.where = m->reference->where;
      s.derive_from = *m->reference;
      s.lowpass_hz = hz;
      s.implicit = true;
      pr.stimuli.push_back(s);
    }
  }
  return pr;
}

Protocol load_protocol(const std::string& path, std::vector<std::string>* problems) {
  const std::string text = read_bounded_file(path, kYamlFileLimit);
  std::string base = std::filesystem::path(path).parent_path().string();
  if (base.empty()) base = ".";
  return parse_protocol(text, path, base, problems);
}

}  // namespace ms
