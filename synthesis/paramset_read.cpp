// read_recipe: YAML text -> ParamSetRecipe, every value checked where it was written.
#include <cmath>
#include <filesystem>

#include "synthesis/bounded_file.hpp"
#include "synthesis/paramset_recipe.hpp"
#include "synthesis/yaml_reader.hpp"

namespace ms {

namespace fs = std::filesystem;

namespace {

constexpr double kMaxDurationS = 600.0;
constexpr long long kMaxModes = 200000;

std::string join(const std::string& a, const std::string& b) { return a.empty() ? b : a + "." + b; }

// The YAML reader of one document, with the recipe it fills (and the locations resolve will need).
struct RecipeReader {
  const YamlReader& r;
  ParamSetRecipe& out;

  void note(const YAML::Node& node, const std::string& key_path) const {
    out.origin.written_at[key_path] = r.where(node, key_path);
  }

  template <class Enum, std::size_t N>
  Enum choice(const YAML::Node& node, const std::string& key_path, const NameTable<Enum, N>& names,
              const std::string& what) const {
    const std::string name = r.text(node, key_path);
    if (const auto value = find_enum(names, name)) return *value;
    r.fail(node, key_path, unknown_name_problem(what, name, names));
  }

  // A number in [lo, hi]; `range` says so in the message.
  double within(const YAML::Node& node, const std::string& key_path, double lo, double hi,
                const std::string& range) const {
    const double v = r.number(node, key_path);
    if (!(v >= lo && v <= hi)) r.fail(node, key_path, "must lie in " + range);
    return v;
  }

  std::uint64_t seed(const YAML::Node& map, const std::string& key_path) const {
    return map["seed"] ? std::uint64_t(r.integer(map["seed"], join(key_path, "seed"))) : 0;
  }

  void timing(const YAML::Node& root) const;
  void inline_modes(const YAML::Node& node) const;
  void modes_model(const YAML::Node& root) const;
  DampingLaw damping(const YAML::Node& node, const std::string& key_path) const;
  std::vector<HitPoint> hit_points(const YAML::Node& node, const char* default_key, double& default_hit,
                                   double hi) const;
  ObjectRecipe object(const YAML::Node& node) const;
  void object_model(const YAML::Node& root) const;
  void excitation(const YAML::Node& node) const;
  void effects(const YAML::Node& fx) const;
  void support_contacts(const YAML::Node& support, SupportDamping& sd) const;
  void doublets(const YAML::Node& node) const;
  void prune(const YAML::Node& node) const;
  void renderer(const YAML::Node& root) const;
  void level(const YAML::Node& node) const;
};

void RecipeReader::timing(const YAML::Node& root) const {
  if (root["description"]) out.description = r.text(root["description"], "description");
  if (root["sample_rate"]) {
    out.sample_rate_hz = r.positive(root["sample_rate"], "sample_rate");
    if (out.sample_rate_hz < 8000 || out.sample_rate_hz > 384000 ||
        out.sample_rate_hz != std::floor(out.sample_rate_hz))
      r.fail(root["sample_rate"], "sample_rate", "must be a whole number of Hz in [8000, 384000]");
  }
  if (!root["duration_s"]) r.fail(root, "", "missing 'duration_s'");
  out.duration_s = r.positive(root["duration_s"], "duration_s");
  if (out.duration_s > kMaxDurationS) r.fail(root["duration_s"], "duration_s", "absurd duration (more than 600 s)");
  if (out.duration_s * out.sample_rate_hz < 1.0) r.fail(root["duration_s"], "duration_s", "shorter than one sample");
}

void RecipeReader::inline_modes(const YAML::Node& node) const {
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string path = "modes[" + std::to_string(i) + "]";
    const YAML::Node m = node[i];
    r.check_keys(m, path, {"freq_hz", "decay_per_s", "amp", "phase_rad"});
    for (const char* k : {"freq_hz", "decay_per_s", "amp"})
      if (!m[k]) r.fail(m, path, std::string("missing '") + k + "'");
    Mode mode;
    mode.freq_hz = r.positive(m["freq_hz"], path + ".freq_hz");
    mode.decay_per_s = r.non_negative(m["decay_per_s"], path + ".decay_per_s");
    mode.amp = r.non_negative(m["amp"], path + ".amp");
    if (m["phase_rad"]) mode.phase_rad = r.number(m["phase_rad"], path + ".phase_rad");
    out.modes.push_back(mode);
  }
}

void RecipeReader::modes_model(const YAML::Node& root) const {
  for (const char* k : {"material", "damping_law", "damping", "specific_modulus_m2_s2", "fundamental_hz"})
    if (root[k]) r.fail(root[k], k, "applies to 'object' models, not to 'modes'");
  const YAML::Node modes = root["modes"];
  note(modes, "modes");
  if (modes.IsSequence()) {
    inline_modes(modes);
  } else if (modes.IsScalar()) {
    out.modes_csv = r.text(modes, "modes");
  } else {
    r.fail(modes, "modes", "expected a list of modes or the path of a modes CSV");
  }
  if (root["amp_scale"]) out.amp_scale = r.positive(root["amp_scale"], "amp_scale");
  if (!root["hit_gains"]) return;
  const YAML::Node hg = root["hit_gains"];
  if (!hg.IsMap()) r.fail(hg, "hit_gains", "expected a map name: [gain per mode]");
  for (auto it = hg.begin(); it != hg.end(); ++it) {
    const std::string key = "hit_gains." + it->first.Scalar();
    note(it->second, key);
    out.hit_gains.push_back({it->first.Scalar(), r.numbers(it->second, key)});
  }
}

DampingLaw RecipeReader::damping(const YAML::Node& node, const std::string& path) const {
  r.check_keys(node, path, {"law", "alpha1", "alpha2", "alpha3", "loss_factor", "relaxation_strength", "relaxation_hz"});
  DampingLaw law;
  if (!node["law"]) r.fail(node, path, "missing 'law' (rayleigh, powerlaw, hybrid, constant_q or relaxation)");
  law.kind = choice(node["law"], join(path, "law"), kDampingKindNames, "damping law");
  auto get = [&](const char* key, double fallback) {
    return node[key] ? r.non_negative(node[key], join(path, key)) : fallback;
  };
  law.alpha1 = get("alpha1", 0.0);
  law.alpha2 = get("alpha2", 0.0);
  law.alpha3 = get("alpha3", 1.0);
  law.loss_factor = get("loss_factor", 0.0);
  law.relaxation_strength = get("relaxation_strength", 0.0);
  law.relaxation_hz = get("relaxation_hz", 0.0);
  for (const char* key : {"relaxation_strength", "relaxation_hz"})
    if (node[key] && law.kind != DampingKind::relaxation)
      r.fail(node[key], join(path, key), "applies to the relaxation law only");
  if (law.kind == DampingKind::constant_q && !node["loss_factor"])
    r.fail(node, path, "constant_q needs 'loss_factor' (D in d = 2 pi f D)");
  return law;
}

// The default hit (object.<default_key>, in [0, hi]) and the named object.hit_points.
std::vector<HitPoint> RecipeReader::hit_points(const YAML::Node& node, const char* default_key,
                                               double& default_hit, double hi) const {
  const std::string range = "[0.000000, " + std::to_string(hi) + "]";
  if (node[default_key]) default_hit = within(node[default_key], join("object", default_key), 0.0, hi, range);
  std::vector<HitPoint> hits;
  if (!node["hit_points"]) return hits;
  const YAML::Node hp = node["hit_points"];
  if (!hp.IsMap()) r.fail(hp, "object.hit_points", "expected a map name: position");
  for (auto it = hp.begin(); it != hp.end(); ++it)
    hits.push_back({it->first.Scalar(), within(it->second, "object.hit_points." + it->first.Scalar(), 0.0, hi, range)});
  return hits;
}

ObjectRecipe RecipeReader::object(const YAML::Node& node) const {
  if (!node.IsMap()) r.fail(node, "object", "expected a map with a 'type'");
  if (!node["type"]) r.fail(node, "object", "missing 'type' (bar, plate or eigenvalues)");
  ObjectRecipe o;
  o.type = choice(node["type"], "object.type", kObjectTypeNames, "object type");
  if (node["max_modes"]) {
    const long long n = r.integer(node["max_modes"], "object.max_modes");
    if (n <= 0 || n > kMaxModes) r.fail(node["max_modes"], "object.max_modes", "must be between 1 and 200000");
    o.max_modes = std::size_t(n);
  }
  if (o.type == ObjectType::eigenvalues) {
    r.check_keys(node, "object", {"type", "lambda0", "gains", "max_modes"});
    if (!node["lambda0"]) r.fail(node, "object", "eigenvalues needs 'lambda0' (a list)");
    o.lambda0 = r.numbers(node["lambda0"], "object.lambda0");
    for (std::size_t i = 0; i < o.lambda0.size(); ++i)
      if (!(o.lambda0[i] > 0)) r.fail(node["lambda0"][i], "object.lambda0[" + std::to_string(i) + "]", "must be > 0");
    if (node["gains"]) o.gains = r.numbers(node["gains"], "object.gains");
    if (node["gains"] && o.gains.size() != o.lambda0.size())
      r.fail(node["gains"], "object.gains", "needs one gain per eigenvalue");
    return o;
  }
  const bool bar = o.type == ObjectType::bar;
  const char* size_key = bar ? "length_m" : "radius_m";
  if (bar) r.check_keys(node, "object", {"type", "length_m", "thickness_m", "hit_position", "hit_points", "max_modes"});
  else r.check_keys(node, "object", {"type", "radius_m", "thickness_m", "poisson", "hit_radius", "hit_points", "max_modes"});
  for (const char* k : {size_key, "thickness_m"})
    if (!node[k]) r.fail(node, "object", std::string(bar ? "bar" : "plate") + " needs '" + k + "'");
  (bar ? o.length_m : o.radius_m) = r.positive(node[size_key], join("object", size_key));
  o.thickness_m = r.positive(node["thickness_m"], "object.thickness_m");
  if (o.thickness_m >= (bar ? o.length_m : o.radius_m))
    r.fail(node["thickness_m"], "object.thickness_m", std::string("must be smaller than ") + size_key);
  if (bar) {
    o.hit_points = hit_points(node, "hit_position", o.hit_position, 1.0);
    return o;
  }
  if (node["poisson"]) o.poisson = r.number(node["poisson"], "object.poisson");
  if (!(o.poisson > 0.0 && o.poisson < 0.5)) r.fail(node["poisson"], "object.poisson", "must lie in (0, 0.5)");
  o.hit_points = hit_points(node, "hit_radius", o.hit_radius, 0.999);
  return o;
}

void RecipeReader::object_model(const YAML::Node& root) const {
  if (const YAML::Node m = root["material"]; m && m.IsMap()) {
    r.check_keys(m, "material", {"file"});
    if (!m["file"]) r.fail(m, "material", "expected a library id or {file: MATERIAL.yaml}");
    note(m["file"], "material.file");
    out.material_file = r.text(m["file"], "material.file");
  } else if (m) {
    note(m, "material");
    out.material = r.text(m, "material");
  }
  if (root["damping"]) out.damping = damping(root["damping"], "damping");
  else if (!root["material"]) r.fail(root, "", "an 'object' model needs a 'material' or a 'damping' law");
  if (root["damping_law"]) {
    note(root["damping_law"], "damping_law");
    out.damping_law = choice(root["damping_law"], "damping_law", kMaterialFitNames, "damping_law");
  }
  if (root["specific_modulus_m2_s2"])
    out.specific_modulus_m2_s2 = r.positive(root["specific_modulus_m2_s2"], "specific_modulus_m2_s2");
  if (root["amp_scale"]) out.amp_scale = r.positive(root["amp_scale"], "amp_scale");
  if (root["fundamental_hz"]) {
    out.fundamental_hz = r.positive(root["fundamental_hz"], "fundamental_hz");
    if (*out.fundamental_hz >= 0.5 * out.sample_rate_hz)
      r.fail(root["fundamental_hz"], "fundamental_hz", "at or above Nyquist");
  }
  out.object = object(root["object"]);
  if (root["hit_gains"]) r.fail(root["hit_gains"], "hit_gains", "objects take 'object.hit_points'");
}

void RecipeReader::excitation(const YAML::Node& e) const {
  r.check_keys(e, "excitation", {"type", "contact_s", "gain"});
  Excitation& x = out.excitation;
  if (e["type"]) x.shape = choice(e["type"], "excitation.type", kPulseShapeNames, "excitation type");
  if (e["gain"]) x.gain = r.positive(e["gain"], "excitation.gain");
  if (x.shape != PulseShape::impulse) {
    if (!e["contact_s"]) r.fail(e, "excitation", "a finite contact needs 'contact_s'");
    x.contact_s = r.positive(e["contact_s"], "excitation.contact_s");
    if (x.contact_s > 0.05) r.fail(e["contact_s"], "excitation.contact_s", "contact longer than 50 ms is not a strike");
  } else if (e["contact_s"]) {
    r.fail(e["contact_s"], "excitation.contact_s", "an impulse has no contact duration");
  }
}

void RecipeReader::effects(const YAML::Node& fx) const {
  r.check_keys(fx, "effects", {"support_damping", "doublets", "noise", "room", "reverb", "transient"});
  const auto needs = [&](const YAML::Node& n, const std::string& path, std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (!n[k]) r.fail(n, path, std::string("needs '") + k + "'");
  };
  if (const YAML::Node n = fx["room"]) {
    r.check_keys(n, "effects.room", {"rt60_s", "drr_db", "seed"});
    needs(n, "effects.room", {"rt60_s", "drr_db"});
    const YAML::Node t = n["rt60_s"];
    if (t.IsSequence()) {
      out.room.rt60_s = r.numbers(t, "effects.room.rt60_s");
      if (out.room.rt60_s.size() != kRoomOctaveCentresHz.size())
        r.fail(t, "effects.room.rt60_s",
               "needs one RT60 for every band or one per octave band 125 Hz ... 8 kHz (7 values), got " +
                   std::to_string(out.room.rt60_s.size()));
    } else {
      out.room.rt60_s = {r.positive(t, "effects.room.rt60_s")};
    }
    for (double v : out.room.rt60_s)
      if (!(v > 0 && v <= 10)) r.fail(t, "effects.room.rt60_s", "must lie in (0, 10] s");
    out.room.drr_db = within(n["drr_db"], "effects.room.drr_db", -40, 60, "[-40, 60] dB");
    out.room.seed = seed(n, "effects.room");
    out.room.enabled = true;
  }
  if (const YAML::Node n = fx["reverb"]) {
    r.check_keys(n, "effects.reverb", {"rt60_s", "level_db", "seed"});
    needs(n, "effects.reverb", {"rt60_s", "level_db"});
    out.reverb.rt60_s = r.positive(n["rt60_s"], "effects.reverb.rt60_s");
    if (out.reverb.rt60_s > 20) r.fail(n["rt60_s"], "effects.reverb.rt60_s", "must lie in (0, 20] s");
    out.reverb.level_db = within(n["level_db"], "effects.reverb.level_db", -120, 20, "[-120, 20] dB");
    out.reverb.seed = seed(n, "effects.reverb");
    out.reverb.enabled = true;
  }
  if (const YAML::Node n = fx["transient"]) {
    r.check_keys(n, "effects.transient", {"level_db", "duration_ms", "seed", "band_hz", "hold_ms"});
    needs(n, "effects.transient", {"level_db", "duration_ms"});
    out.transient.level_db = within(n["level_db"], "effects.transient.level_db", -120, 20, "[-120, 20] dB");
    out.transient.duration_ms = r.positive(n["duration_ms"], "effects.transient.duration_ms");
    if (out.transient.duration_ms > 100)
      r.fail(n["duration_ms"], "effects.transient.duration_ms", "must lie in (0, 100] ms (a longer burst is not an attack)");
    out.transient.seed = seed(n, "effects.transient");
    if (const YAML::Node band = n["band_hz"]) {
      const std::vector<double> edges = r.numbers(band, "effects.transient.band_hz");
      if (edges.size() != 2 || !(edges[0] >= 0.0 && edges[0] < edges[1] && edges[1] <= 0.5 * out.sample_rate_hz))
        r.fail(band, "effects.transient.band_hz", "must be [low, high] with 0 <= low < high <= Nyquist (Hz)");
      out.transient.low_hz = edges[0];
      out.transient.high_hz = edges[1];
    }
    if (n["hold_ms"]) out.transient.hold_ms = within(n["hold_ms"], "effects.transient.hold_ms", 0, 50, "[0, 50] ms");
    out.transient.enabled = true;
  }
  if (const YAML::Node n = fx["noise"]) {
    r.check_keys(n, "effects.noise", {"snr_db", "seed"});
    needs(n, "effects.noise", {"snr_db"});
    out.noise.snr_db = within(n["snr_db"], "effects.noise.snr_db", -20, 200, "[-20, 200] dB");
    out.noise.seed = seed(n, "effects.noise");
    out.noise.enabled = true;
  }
  if (const YAML::Node s = fx["support_damping"]) {
    const std::string path = "effects.support_damping";
    r.check_keys(s, path, {"extra_decay_per_s", "per_mode_decay_per_s", "exponential_mean_per_s", "seed",
                           "contacts", "mu", "c"});
    SupportDamping& sd = out.support_damping.emplace();
    support_contacts(s, sd);
    if (s["extra_decay_per_s"]) sd.extra_decay_per_s = r.non_negative(s["extra_decay_per_s"], path + ".extra_decay_per_s");
    if (s["per_mode_decay_per_s"]) {
      sd.per_mode_decay_per_s = r.numbers(s["per_mode_decay_per_s"], path + ".per_mode_decay_per_s");
      for (double v : sd.per_mode_decay_per_s)
        if (v < 0) r.fail(s["per_mode_decay_per_s"], path + ".per_mode_decay_per_s", "must not be negative");
    }
    if (s["exponential_mean_per_s"])
      sd.exponential_mean_per_s = r.non_negative(s["exponential_mean_per_s"], path + ".exponential_mean_per_s");
    sd.seed = seed(s, path);
  }
  if (fx["doublets"]) doublets(fx["doublets"]);
}

// effects.support_damping's Zheng-James keys: contacts (a position, or {position, c, normal_deg}), mu, c.
void RecipeReader::support_contacts(const YAML::Node& s, SupportDamping& sd) const {
  const std::string path = "effects.support_damping";
  const YAML::Node contacts = s["contacts"];
  if (!contacts) {
    for (const char* k : {"mu", "c"})
      if (s[k]) r.fail(s[k], join(path, k), "applies to 'contacts' (none are given)");
    return;
  }
  const std::string list = join(path, "contacts");
  if (!out.object || out.object->type == ObjectType::eigenvalues)
    r.fail(contacts, list, "contacts need an object's mode shapes: 'object: {type: bar}' or 'plate'");
  if (!contacts.IsSequence() || contacts.size() == 0)
    r.fail(contacts, list, "expected a list of contacts: a position, or {position, c, normal_deg}");
  const bool bar = out.object->type == ObjectType::bar;
  const double hi = bar ? 1.0 : 0.999;
  const std::string range = bar ? "[0, 1] (of the length)" : "[0, 0.999] (of the radius)";
  if (!s["mu"]) r.fail(s, path, "contacts need 'mu' (the friction coefficient, in [0, 1])");
  sd.mu = within(s["mu"], join(path, "mu"), 0.0, 1.0, "[0, 1]");
  if (s["c"]) sd.c_per_s = r.non_negative(s["c"], join(path, "c"));
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const YAML::Node node = contacts[k];
    const std::string at = list + "[" + std::to_string(k) + "]";
    SupportContact& contact = sd.contacts.emplace_back();
    if (!node.IsMap()) {
      contact.position = within(node, at, 0.0, hi, range);
    } else {
      r.check_keys(node, at, {"position", "c", "normal_deg"});
      if (!node["position"]) r.fail(node, at, "missing 'position'");
      contact.position = within(node["position"], join(at, "position"), 0.0, hi, range);
      if (node["c"]) contact.c_per_s = r.non_negative(node["c"], join(at, "c"));
      if (node["normal_deg"])
        contact.normal_deg = within(node["normal_deg"], join(at, "normal_deg"), 0.0, 90.0, "[0, 90] degrees");
    }
    if (!contact.c_per_s && !sd.c_per_s)
      r.fail(node, at, "needs 'c': its own ({position, c}) or the support's (support_damping.c)");
  }
}

void RecipeReader::doublets(const YAML::Node& d) const {
  r.check_keys(d, "effects.doublets", {"split_rel", "split_hz", "balance", "min_order"});
  note(d, "effects.doublets");
  Doublets& db = out.doublets.emplace();
  // A doublet is one mode split a little by imperfection, into f -+ split/2: a split of f or more
  // would put the lower mode at or below f/2 (and at 2 f below 0 Hz).
  if (d["split_rel"]) {
    db.split_rel = r.positive(d["split_rel"], "effects.doublets.split_rel");
    if (db.split_rel >= 1.0)
      r.fail(d["split_rel"], "effects.doublets.split_rel",
             "must lie in (0, 1): the two modes lie at f (1 -+ split_rel/2), got " + d["split_rel"].Scalar());
  }
  if (d["split_hz"]) {
    note(d["split_hz"], "effects.doublets.split_hz");
    db.split_hz = r.positive(d["split_hz"], "effects.doublets.split_hz");
  }
  if (db.split_rel <= 0 && db.split_hz <= 0) r.fail(d, "effects.doublets", "needs split_rel or split_hz");
  if (d["balance"]) db.balance = within(d["balance"], "effects.doublets.balance", 0, 1, "[0, 1]");
  if (d["min_order"]) db.min_order = int(r.integer(d["min_order"], "effects.doublets.min_order"));
}

void RecipeReader::prune(const YAML::Node& pr) const {
  r.check_keys(pr, "prune", {"method", "threshold_db", "playback_db", "combine", "order", "keep"});
  note(pr, "prune");
  for (auto it = pr.begin(); it != pr.end(); ++it) note(it->second, "prune." + it->first.Scalar());
  PruneRecipe& p = out.prune.emplace();
  if (pr["method"]) p.options.method = choice(pr["method"], "prune.method", kPruneMethodNames, "value");
  if (pr["combine"]) p.options.combine = choice(pr["combine"], "prune.combine", kMaskingCombineNames, "value");
  if (pr["order"]) p.options.order = choice(pr["order"], "prune.order", kModeOrderNames, "value");
  if (pr["threshold_db"]) p.options.threshold_db = r.number(pr["threshold_db"], "prune.threshold_db");
  if (pr["playback_db"]) p.options.playback_db = r.number(pr["playback_db"], "prune.playback_db");
  if (pr["keep"]) {
    const long long k = r.integer(pr["keep"], "prune.keep");
    if (k <= 0) r.fail(pr["keep"], "prune.keep", "must be at least 1");
    p.keep = std::size_t(k);
  }
}

void RecipeReader::level(const YAML::Node& l) const {
  r.check_keys(l, "level", {"normalize", "target_dbfs", "attack_window_s"});
  OutputLevel& target = out.level;
  if (l["normalize"]) target.mode = choice(l["normalize"], "level.normalize", kLevelModeNames, "normalize");
  target.target_dbfs = default_target_dbfs(target.mode);
  if (l["target_dbfs"]) target.target_dbfs = within(l["target_dbfs"], "level.target_dbfs", -120, 0, "[-120, 0] dBFS");
  if (l["attack_window_s"]) {
    target.attack_window_s = r.positive(l["attack_window_s"], "level.attack_window_s");
    if (target.attack_window_s > out.duration_s) r.fail(l["attack_window_s"], "level.attack_window_s", "longer than the sound");
  }
}

// `renderer:`, its `bandpass:` section and `phase:`.
void RecipeReader::renderer(const YAML::Node& root) const {
  if (root["phase"]) out.phase = choice(root["phase"], "phase", kOnsetPhaseNames, "phase");
  if (root["renderer"]) out.renderer = choice(root["renderer"], "renderer", kRendererNames, "renderer");
  const YAML::Node b = root["bandpass"];
  if (out.renderer != Renderer::bandpass) {
    if (b) r.fail(b, "bandpass", "band-pass filters are used with 'renderer: bandpass' only");
    return;
  }
  if (!b) r.fail(root["renderer"], "renderer", "'renderer: bandpass' needs 'bandpass: {q: ...}' or 'bandpass: {material: ...}'");
  r.check_keys(b, "bandpass", {"q", "material", "q_table", "clip"});
  note(b, "bandpass");
  BandpassRecipe& bp = out.bandpass.emplace();
  if (b["q"] && b["material"]) r.fail(b, "bandpass", "give either 'q' or 'material', not both");
  if (const YAML::Node q = b["q"]) {
    note(q, "bandpass.q");
    bp.q = q.IsSequence() ? r.numbers(q, "bandpass.q") : std::vector<double>{r.number(q, "bandpass.q")};
    for (std::size_t i = 0; i < bp.q.size(); ++i)
      if (!(bp.q[i] > 0.0 && bp.q[i] <= 1e6)) r.fail(q.IsSequence() ? q[i] : q, "bandpass.q", "must lie in (0, 1e6]");
    if (bp.q.empty()) r.fail(q, "bandpass.q", "needs one Q, or one per mode");
    if (b["q_table"]) r.fail(b["q_table"], "bandpass.q_table", "picks a material's Q: give 'material' instead of 'q'");
  } else if (b["material"]) {
    bp.material = choice(b["material"], "bandpass.material", kBandpassMaterialNames, "band-pass material");
    if (b["q_table"]) bp.q_table = choice(b["q_table"], "bandpass.q_table", kQTableNames, "Q table");
  } else {
    r.fail(b, "bandpass", "needs 'q' (one, or one per mode) or 'material' (plastic, wood, ceramic, glass, metal)");
  }
  if (b["clip"]) bp.clip = r.non_negative(b["clip"], "bandpass.clip");
  if (out.excitation.shape != PulseShape::impulse)
    r.fail(root["excitation"], "excitation", "the band-pass renderer is excited by an impulse (type: impulse)");
}

}  // namespace

double default_target_dbfs(LevelMode mode) { return mode == LevelMode::attack_rms ? -20.0 : -1.0; }

ParamSetRecipe read_recipe(const std::string& yaml_text, const std::string& file, const std::string& base_dir,
                           const std::vector<std::string>& overrides) {
  const YamlReader probe(file);
  YAML::Node root = probe.load(yaml_text);
  if (!root.IsDefined() || root.IsNull()) throw InputError(SourceLocation{file, 1, 1}, "empty parameter set");
  if (!root.IsMap()) probe.fail(root, "", "a parameter set is a map of keys (sample_rate, duration_s, ...)");
  const YamlReader r(file, apply_overrides(root, overrides));
  r.check_keys(root, "", {"description", "sample_rate", "duration_s", "modes", "object", "material",
                          "damping_law", "damping", "specific_modulus_m2_s2", "stiffness_scale",
                          "size_scale", "amp_scale", "fundamental_hz", "hit", "hit_gains",
                          "excitation", "effects", "prune", "level", "output", "residual", "renderer",
                          "bandpass", "phase"});
  ParamSetRecipe recipe;
  recipe.origin.file = file;
  recipe.origin.base_dir = base_dir;
  const RecipeReader read{r, recipe};
  read.note(root, "");
  read.timing(root);
  const bool has_modes = bool(root["modes"]), has_object = bool(root["object"]);
  if (has_modes == has_object)
    r.fail(root, "", has_modes ? "give either 'modes' or 'object', not both"
                               : "no model: give 'modes' (list or CSV path) or 'object'");
  if (root["stiffness_scale"]) recipe.stiffness_scale = r.positive(root["stiffness_scale"], "stiffness_scale");
  if (root["size_scale"]) recipe.size_scale = r.positive(root["size_scale"], "size_scale");
  if (has_modes) read.modes_model(root);
  else read.object_model(root);
  if (root["hit"]) {
    read.note(root["hit"], "hit");
    recipe.hit = r.text(root["hit"], "hit");
  }
  if (root["excitation"]) read.excitation(root["excitation"]);
  if (root["effects"]) read.effects(root["effects"]);
  if (root["prune"]) read.prune(root["prune"]);
  if (const YAML::Node n = root["residual"]) {
    r.check_keys(n, "residual", {"file", "gain_db", "seed"});
    if (!n["file"]) r.fail(n, "residual", "expected {file: MATERIAL.residual.msr, gain_db, seed}");
    read.note(n["file"], "residual.file");
    recipe.residual = ResidualRecipe{r.text(n["file"], "residual.file"), 0.0, read.seed(n, "residual")};
    if (n["gain_db"]) recipe.residual->gain_db = read.within(n["gain_db"], "residual.gain_db", -120, 40, "[-120, 40] dB");
  }
  read.renderer(root);
  if (root["level"]) read.level(root["level"]);
  if (const YAML::Node o = root["output"]) {
    r.check_keys(o, "output", {"format"});
    if (o["format"]) {
      read.note(o["format"], "output.format");
      recipe.format = read.choice(o["format"], "output.format", kSampleFormatNames, "sample format");
    }
  }
  return recipe;
}

ParamSetRecipe read_recipe_file(const std::string& path, const std::vector<std::string>& overrides) {
  const std::string text = read_bounded_file(path, kYamlFileLimit);
  const fs::path base = fs::path(path).has_parent_path() ? fs::path(path).parent_path() : fs::path(".");
  return read_recipe(text, path, base.string(), overrides);
}

SourceLocation RecipeOrigin::where(const std::string& key_path) const {
  if (const auto it = written_at.find(key_path); it != written_at.end()) return it->second;
  return SourceLocation{file, key_path.empty() ? 1 : 0, key_path.empty() ? 1 : 0};
}

void RecipeOrigin::fail(const std::string& key_path, const std::string& problem) const {
  throw InputError(where(key_path), key_path.empty() ? problem : key_path + ": " + problem);
}

}  // namespace ms
