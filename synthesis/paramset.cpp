#include "synthesis/paramset.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>

#include "synthesis/bounded_file.hpp"
#include "synthesis/damping_law.hpp"
#include "synthesis/masking_pruning.hpp"
#include "synthesis/material.hpp"
#include "synthesis/material_file.hpp"
#include "synthesis/modes_csv.hpp"
#include "synthesis/reference_objects.hpp"
#include "synthesis/sha256.hpp"
#include "synthesis/yaml_reader.hpp"

namespace ms {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRendererVersion = "modalstudy-render-1";
constexpr double kMaxDurationS = 600.0;
constexpr std::size_t kMaxModes = 200000;

std::string join(const std::string& a, const std::string& b) { return a.empty() ? b : a + "." + b; }

struct ObjectSpec {
  std::string type;
  std::vector<double> lambda0;
  std::vector<int> orders;
  std::vector<std::string> hit_names;
  std::vector<std::vector<double>> hit_gains;
};

DampingLaw read_damping(const YamlReader& r, const YAML::Node& node, const std::string& path) {
  r.check_keys(node, path, {"law", "alpha1", "alpha2", "alpha3", "loss_factor"});
  DampingLaw law;
  if (!node["law"]) r.fail(node, path, "missing 'law' (rayleigh, powerlaw, hybrid or constant_q)");
  try {
    law.kind = parse_damping_kind(r.text(node["law"], join(path, "law")));
  } catch (const std::invalid_argument& e) {
    r.fail(node["law"], join(path, "law"), e.what());
  }
  auto get = [&](const char* key, double fallback) {
    return node[key] ? r.non_negative(node[key], join(path, key)) : fallback;
  };
  law.alpha1 = get("alpha1", 0.0);
  law.alpha2 = get("alpha2", 0.0);
  law.alpha3 = get("alpha3", 1.0);
  law.loss_factor = get("loss_factor", 0.0);
  if (law.kind == DampingKind::constant_q && !node["loss_factor"])
    r.fail(node, path, "constant_q needs 'loss_factor' (D in d = 2 pi f D)");
  return law;
}

// Eigenvalues (for E/rho = 1) and hit-point gains of an analytic object, up to max_lambda0.
ObjectSpec read_object(const YamlReader& r, const YAML::Node& node, double max_lambda0_of_unit,
                       bool unit_scale_unknown) {
  if (!node.IsMap()) r.fail(node, "object", "expected a map with a 'type'");
  if (!node["type"]) r.fail(node, "object", "missing 'type' (bar, plate or eigenvalues)");
  ObjectSpec spec;
  spec.type = r.text(node["type"], "object.type");
  struct Hits {
    std::vector<std::string> names;
    std::vector<double> positions;
  };
  auto hit_list = [&](const char* default_key, double fallback, double lo, double hi) {
    Hits hits;
    const std::string key = join("object", default_key);
    const double def = node[default_key] ? r.number(node[default_key], key) : fallback;
    if (!(def >= lo && def <= hi))
      r.fail(node[default_key], key, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    hits.names.push_back("default");
    hits.positions.push_back(def);
    if (node["hit_points"]) {
      const YAML::Node hp = node["hit_points"];
      if (!hp.IsMap()) r.fail(hp, "object.hit_points", "expected a map name: position");
      for (auto it = hp.begin(); it != hp.end(); ++it) {
        const std::string point = "object.hit_points." + it->first.Scalar();
        const double v = r.number(it->second, point);
        if (!(v >= lo && v <= hi))
          r.fail(it->second, point, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        hits.names.push_back(it->first.Scalar());
        hits.positions.push_back(v);
      }
    }
    return hits;
  };
  const std::size_t max_modes =
      node["max_modes"] ? std::size_t(r.integer(node["max_modes"], "object.max_modes")) : 2000;
  if (max_modes == 0 || max_modes > kMaxModes)
    r.fail(node["max_modes"], "object.max_modes", "must be between 1 and 200000");
  if (spec.type == "bar") {
    r.check_keys(node, "object", {"type", "length_m", "thickness_m", "hit_position", "hit_points",
                                  "max_modes"});
    for (const char* k : {"length_m", "thickness_m"})
      if (!node[k]) r.fail(node, "object", std::string("bar needs '") + k + "'");
    const double L = r.positive(node["length_m"], "object.length_m");
    const double h = r.positive(node["thickness_m"], "object.thickness_m");
    if (h >= L) r.fail(node["thickness_m"], "object.thickness_m", "must be smaller than length_m");
    const auto hits = hit_list("hit_position", 0.1, 0.0, 1.0);
    const double limit = unit_scale_unknown ? free_free_bar(L, h, {}, 1e300, 1).lambda0[0] * 1.0001
                                            : max_lambda0_of_unit;
    const ObjectModes om = free_free_bar(L, h, hits.positions, limit, unit_scale_unknown ? 1 : max_modes);
    spec.lambda0 = om.lambda0;
    spec.orders = om.circumferential_order;
    spec.hit_names = hits.names;
    spec.hit_gains = om.gains;
  } else if (spec.type == "plate") {
    r.check_keys(node, "object", {"type", "radius_m", "thickness_m", "poisson", "hit_radius",
                                  "hit_points", "max_modes"});
    for (const char* k : {"radius_m", "thickness_m"})
      if (!node[k]) r.fail(node, "object", std::string("plate needs '") + k + "'");
    const double a = r.positive(node["radius_m"], "object.radius_m");
    const double h = r.positive(node["thickness_m"], "object.thickness_m");
    if (h >= a) r.fail(node["thickness_m"], "object.thickness_m", "must be smaller than radius_m");
    const double nu = node["poisson"] ? r.number(node["poisson"], "object.poisson") : 0.33;
    if (!(nu > 0.0 && nu < 0.5)) r.fail(node["poisson"], "object.poisson", "must lie in (0, 0.5)");
    const auto hits = hit_list("hit_radius", 0.3, 0.0, 0.999);
    // The fundamental of a free plate is the (2 nodal diameters, 0 circles) mode.
    const double k0 = free_plate_roots(2, nu, 4.0).at(0);
    const double stiff = h * h / (12.0 * (1.0 - nu * nu));
    const double first = std::pow(k0, 4) * stiff / std::pow(a, 4);
    const double limit = unit_scale_unknown ? first * 1.0001 : max_lambda0_of_unit;
    const ObjectModes om =
        free_circular_plate(a, h, nu, hits.positions, limit, unit_scale_unknown ? 1 : max_modes);
    spec.lambda0 = om.lambda0;
    spec.orders = om.circumferential_order;
    spec.hit_names = hits.names;
    spec.hit_gains = om.gains;
  } else if (spec.type == "eigenvalues") {
    r.check_keys(node, "object", {"type", "lambda0", "gains", "max_modes"});
    if (!node["lambda0"]) r.fail(node, "object", "eigenvalues needs 'lambda0' (a list)");
    spec.lambda0 = r.numbers(node["lambda0"], "object.lambda0");
    for (std::size_t i = 0; i < spec.lambda0.size(); ++i)
      if (!(spec.lambda0[i] > 0))
        r.fail(node["lambda0"][i], "object.lambda0[" + std::to_string(i) + "]", "must be > 0");
    std::vector<double> gains = node["gains"] ? r.numbers(node["gains"], "object.gains")
                                              : std::vector<double>(spec.lambda0.size(), 1.0);
    if (gains.size() != spec.lambda0.size())
      r.fail(node["gains"], "object.gains", "needs one gain per eigenvalue");
    spec.orders.assign(spec.lambda0.size(), 0);
    spec.hit_names = {"default"};
    spec.hit_gains = {gains};
  } else {
    r.fail(node["type"], "object.type",
           "unknown object type '" + spec.type + "' (expected bar, plate or eigenvalues)");
  }
  return spec;
}

// A file the set names, relative to the set's folder; it must lie inside `confinement` (without one,
// inside paramset_confinement of that folder).
fs::path confined_file(const YamlReader& r, const YAML::Node& node, const std::string& key_path,
                       const std::string& base_dir, const Confinement* confinement) {
  const std::string written = r.text(node, key_path);
  const Confinement own = confinement ? Confinement::anywhere() : paramset_confinement(base_dir);
  const Confinement& allowed = confinement ? *confinement : own;
  if (const std::string problem = allowed.problem(written, base_dir); !problem.empty())
    r.fail(node, key_path, problem);
  fs::path file(written);
  if (file.is_relative()) file = fs::path(base_dir) / file;
  return file;
}

// `material: {file: X.yaml}`: a material file (material_file.hpp), relative to the set's folder and
// inside the set's confinement like a modes CSV.
Material read_material_reference(const YamlReader& r, const YAML::Node& node, const std::string& base_dir,
                                 const Confinement* confinement) {
  r.check_keys(node, "material", {"file"});
  if (!node["file"]) r.fail(node, "material", "expected a library id or {file: MATERIAL.yaml}");
  const fs::path file = confined_file(r, node["file"], "material.file", base_dir, confinement);
  try {
    return read_material_file(file.string());
  } catch (const InputError& e) {
    if (e.where().line > 0) throw;
    r.fail(node["file"], "material.file", "cannot use '" + file.string() + "': " + e.problem());
  }
}

std::vector<Mode> read_inline_modes(const YamlReader& r, const YAML::Node& node) {
  std::vector<Mode> modes;
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
    modes.push_back(mode);
  }
  return modes;
}

}  // namespace

ParamSet parse_paramset(const std::string& yaml_text, const std::string& file,
                        const std::string& base_dir, const std::vector<std::string>& overrides,
                        const Confinement* confinement) {
  YamlReader probe(file);
  YAML::Node root = probe.load(yaml_text);
  if (!root.IsDefined() || root.IsNull()) throw InputError(SourceLocation{file, 1, 1}, "empty parameter set");
  if (!root.IsMap()) probe.fail(root, "", "a parameter set is a map of keys (sample_rate, duration_s, ...)");
  const std::vector<std::string> overridden = apply_overrides(root, overrides);
  const YamlReader r(file, overridden);
  r.check_keys(root, "", {"description", "sample_rate", "duration_s", "modes", "object", "material",
                          "damping_law", "damping", "specific_modulus_m2_s2", "stiffness_scale",
                          "size_scale", "amp_scale", "fundamental_hz", "hit", "hit_gains",
                          "excitation", "effects", "prune", "level", "output"});
  ParamSet p;
  p.source = file;
  p.format_where = SourceLocation{file, 0, 0};
  if (root["description"]) p.description = r.text(root["description"], "description");
  if (root["sample_rate"]) {
    p.sample_rate_hz = r.positive(root["sample_rate"], "sample_rate");
    if (p.sample_rate_hz < 8000 || p.sample_rate_hz > 384000 ||
        p.sample_rate_hz != std::floor(p.sample_rate_hz))
      r.fail(root["sample_rate"], "sample_rate", "must be a whole number of Hz in [8000, 384000]");
  }
  if (!root["duration_s"]) r.fail(root, "", "missing 'duration_s'");
  p.duration_s = r.positive(root["duration_s"], "duration_s");
  if (p.duration_s > kMaxDurationS)
    r.fail(root["duration_s"], "duration_s", "absurd duration (more than 600 s)");
  if (p.duration_s * p.sample_rate_hz < 1.0)
    r.fail(root["duration_s"], "duration_s", "shorter than one sample");

  const bool has_modes = bool(root["modes"]), has_object = bool(root["object"]);
  if (has_modes == has_object)
    r.fail(root, "", has_modes ? "give either 'modes' or 'object', not both"
                               : "no model: give 'modes' (list or CSV path) or 'object'");
  const double stiffness_scale =
      root["stiffness_scale"] ? r.positive(root["stiffness_scale"], "stiffness_scale") : 1.0;
  const double size_scale = root["size_scale"] ? r.positive(root["size_scale"], "size_scale") : 1.0;
  const double nyquist = 0.5 * p.sample_rate_hz;
  std::vector<int> orders;

  if (has_modes) {
    for (const char* k : {"material", "damping_law", "damping", "specific_modulus_m2_s2",
                          "fundamental_hz"})
      if (root[k]) r.fail(root[k], k, "applies to 'object' models, not to 'modes'");
    const YAML::Node modes = root["modes"];
    if (modes.IsSequence()) {
      p.model.modes = read_inline_modes(r, modes);
    } else if (modes.IsScalar()) {
      const fs::path csv = confined_file(r, modes, "modes", base_dir, confinement);
      try {
        p.model = parse_modes_csv(read_bounded_file(csv.string(), kCsvFileLimit), csv.string());
      } catch (const InputError& e) {
        if (e.where().line > 0) throw;
        r.fail(modes, "modes", "cannot use '" + csv.string() + "': " + e.problem());
      }
    } else {
      r.fail(modes, "modes", "expected a list of modes or the path of a modes CSV");
    }
    // Uniform size scaling and stiffness scaling move frequencies: f * sqrt(stiffness) / size.
    const double fscale = std::sqrt(stiffness_scale) / size_scale;
    const double amp_scale = root["amp_scale"] ? r.positive(root["amp_scale"], "amp_scale") : 1.0;
    for (Mode& m : p.model.modes) {
      m.freq_hz *= fscale;
      m.amp *= amp_scale;
    }
    if (root["hit_gains"]) {
      const YAML::Node hg = root["hit_gains"];
      if (!hg.IsMap()) r.fail(hg, "hit_gains", "expected a map name: [gain per mode]");
      for (auto it = hg.begin(); it != hg.end(); ++it) {
        const std::string key = "hit_gains." + it->first.Scalar();
        auto gains = r.numbers(it->second, key);
        if (gains.size() != p.model.modes.size())
          r.fail(it->second, key, "needs one gain per mode (" + std::to_string(p.model.modes.size()) + ")");
        p.model.hit_point_names.push_back(it->first.Scalar());
        p.model.hit_gains.push_back(std::move(gains));
      }
    }
  } else {
    // Material: damping law, specific modulus and amplitude scale; each can be overridden.
    const Material* material = nullptr;
    std::optional<Material> from_file;
    if (root["material"] && root["material"].IsMap()) {
      from_file = read_material_reference(r, root["material"], base_dir, confinement);
      material = &*from_file;
    } else if (root["material"]) {
      const std::string id = r.text(root["material"], "material");
      material = find_material(id);
      if (!material) {
        const std::string near = nearest_key(id, material_ids());
        r.fail(root["material"], "material",
               "unknown material '" + id + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
      }
    }
    DampingLaw law;
    if (root["damping"]) {
      law = read_damping(r, root["damping"], "damping");
    } else if (material) {
      law = material->rayleigh;
      if (root["damping_law"]) {
        const std::string which = r.text(root["damping_law"], "damping_law");
        if (which == "hybrid") {
          if (!material->hybrid) r.fail(root["damping_law"], "damping_law", material->id + " has no hybrid fit");
          law = *material->hybrid;
        } else if (which != "rayleigh") {
          r.fail(root["damping_law"], "damping_law", "expected rayleigh or hybrid");
        }
      }
    } else {
      r.fail(root, "", "an 'object' model needs a 'material' or a 'damping' law");
    }
    double gamma = material ? material->specific_modulus_m2_s2 : 0.0;
    if (root["specific_modulus_m2_s2"])
      gamma = r.positive(root["specific_modulus_m2_s2"], "specific_modulus_m2_s2");
    const bool fundamental = bool(root["fundamental_hz"]);
    if (gamma <= 0.0 && !fundamental)
      r.fail(root, "", "give 'specific_modulus_m2_s2' (E/rho) or 'fundamental_hz' for the stiffness");
    const double amp_scale = root["amp_scale"] ? r.positive(root["amp_scale"], "amp_scale")
                                               : (material ? material->amp_scale : 1.0);
    double scale = gamma * stiffness_scale / (size_scale * size_scale);  // lambda = scale * lambda0
    if (fundamental) {
      const double f0 = r.positive(root["fundamental_hz"], "fundamental_hz");
      if (f0 >= nyquist) r.fail(root["fundamental_hz"], "fundamental_hz", "at or above Nyquist");
      const ObjectSpec first = read_object(r, root["object"], 0.0, true);
      scale = std::pow(2.0 * std::numbers::pi * f0, 2) / first.lambda0.at(0);
    }
    const double max_lambda0 = std::pow(2.0 * std::numbers::pi * nyquist, 2) * 1.2 / scale;  // damping lowers f
    const ObjectSpec spec = read_object(r, root["object"], max_lambda0, false);
    // The hit point sets the amplitudes: the mode shapes at that point.
    std::size_t hit_index = 0;
    if (root["hit"]) {
      const std::string hit = r.text(root["hit"], "hit");
      const auto it = std::find(spec.hit_names.begin(), spec.hit_names.end(), hit);
      if (it == spec.hit_names.end()) {
        const std::string near = nearest_key(hit, spec.hit_names);
        r.fail(root["hit"], "hit", "unknown hit point '" + hit + "'" +
                                       (near.empty() ? "" : " (did you mean '" + near + "'?)"));
      }
      hit_index = std::size_t(it - spec.hit_names.begin());
    }
    std::size_t overdamped = 0;
    p.model = modes_from_eigenvalues(spec.lambda0, law, scale, amp_scale, spec.hit_gains[hit_index],
                                     &overdamped);
    if (overdamped > 0)
      p.warnings.push_back(std::to_string(overdamped) + " overdamped mode(s) dropped");
    // Keep the circumferential orders aligned with the surviving modes (for doublets).
    for (std::size_t i = 0; i < spec.lambda0.size(); ++i) {
      const double lambda = scale * spec.lambda0[i], d = law.decay_per_s(lambda);
      if (lambda - d * d > 0) orders.push_back(spec.orders[i]);
    }
    // An analytic object has infinitely many modes: truncate the series at Nyquist (no warning;
    // only modes a person listed explicitly warn when they cannot sound).
    std::vector<Mode> below;
    std::vector<int> below_orders;
    for (std::size_t i = 0; i < p.model.modes.size(); ++i)
      if (p.model.modes[i].freq_hz < nyquist) {
        below.push_back(p.model.modes[i]);
        below_orders.push_back(orders[i]);
      }
    p.model.modes = std::move(below);
    orders = std::move(below_orders);
    if (root["hit_gains"]) r.fail(root["hit_gains"], "hit_gains", "objects take 'object.hit_points'");
  }
  if (p.model.modes.size() > kMaxModes)
    r.fail(root, "", "too many modes (" + std::to_string(p.model.modes.size()) + " > 200000)");

  if (has_modes && root["hit"]) {
    const std::string hit = r.text(root["hit"], "hit");
    const auto& names = p.model.hit_point_names;
    const auto it = std::find(names.begin(), names.end(), hit);
    if (it == names.end()) {
      const std::string near = nearest_key(hit, names);
      r.fail(root["hit"], "hit", "unknown hit point '" + hit + "'" +
                                     (near.empty() ? "" : " (did you mean '" + near + "'?)"));
    }
    const ModalModel hit_model = at_hit_point(p.model, std::size_t(it - names.begin()));
    p.model.modes = hit_model.modes;
  }

  if (root["excitation"]) {
    const YAML::Node e = root["excitation"];
    r.check_keys(e, "excitation", {"type", "contact_s", "gain"});
    if (e["type"]) {
      try {
        p.excitation.shape = parse_pulse_shape(r.text(e["type"], "excitation.type"));
      } catch (const std::invalid_argument& err) {
        r.fail(e["type"], "excitation.type", err.what());
      }
    }
    if (e["gain"]) p.excitation.gain = r.positive(e["gain"], "excitation.gain");
    if (p.excitation.shape != PulseShape::impulse) {
      if (!e["contact_s"]) r.fail(e, "excitation", "a finite contact needs 'contact_s'");
      p.excitation.contact_s = r.positive(e["contact_s"], "excitation.contact_s");
      if (p.excitation.contact_s > 0.05)
        r.fail(e["contact_s"], "excitation.contact_s", "contact longer than 50 ms is not a strike");
    } else if (e["contact_s"]) {
      r.fail(e["contact_s"], "excitation.contact_s", "an impulse has no contact duration");
    }
  }

  if (root["effects"]) {
    const YAML::Node fx = root["effects"];
    r.check_keys(fx, "effects", {"support_damping", "doublets", "noise", "reverb", "transient"});
    if (fx["reverb"]) {
      const YAML::Node n = fx["reverb"];
      r.check_keys(n, "effects.reverb", {"rt60_s", "level_db", "seed"});
      if (!n["rt60_s"]) r.fail(n, "effects.reverb", "needs 'rt60_s'");
      if (!n["level_db"]) r.fail(n, "effects.reverb", "needs 'level_db'");
      p.reverb.rt60_s = r.positive(n["rt60_s"], "effects.reverb.rt60_s");
      if (p.reverb.rt60_s > 20) r.fail(n["rt60_s"], "effects.reverb.rt60_s", "must lie in (0, 20] s");
      p.reverb.level_db = r.number(n["level_db"], "effects.reverb.level_db");
      if (!(p.reverb.level_db >= -120 && p.reverb.level_db <= 20))
        r.fail(n["level_db"], "effects.reverb.level_db", "must lie in [-120, 20] dB");
      if (n["seed"]) p.reverb.seed = std::uint64_t(r.integer(n["seed"], "effects.reverb.seed"));
      p.reverb.enabled = true;
    }
    if (fx["transient"]) {
      const YAML::Node n = fx["transient"];
      r.check_keys(n, "effects.transient", {"level_db", "duration_ms", "seed"});
      if (!n["level_db"]) r.fail(n, "effects.transient", "needs 'level_db'");
      if (!n["duration_ms"]) r.fail(n, "effects.transient", "needs 'duration_ms'");
      p.transient.level_db = r.number(n["level_db"], "effects.transient.level_db");
      if (!(p.transient.level_db >= -120 && p.transient.level_db <= 20))
        r.fail(n["level_db"], "effects.transient.level_db", "must lie in [-120, 20] dB");
      p.transient.duration_ms = r.positive(n["duration_ms"], "effects.transient.duration_ms");
      if (p.transient.duration_ms > 100)
        r.fail(n["duration_ms"], "effects.transient.duration_ms", "must lie in (0, 100] ms (a longer burst is not an attack)");
      if (n["seed"]) p.transient.seed = std::uint64_t(r.integer(n["seed"], "effects.transient.seed"));
      p.transient.enabled = true;
    }
    if (fx["noise"]) {
      const YAML::Node n = fx["noise"];
      r.check_keys(n, "effects.noise", {"snr_db", "seed"});
      if (!n["snr_db"]) r.fail(n, "effects.noise", "needs 'snr_db'");
      p.noise.snr_db = r.number(n["snr_db"], "effects.noise.snr_db");
      if (p.noise.snr_db < -20 || p.noise.snr_db > 200)
        r.fail(n["snr_db"], "effects.noise.snr_db", "must lie in [-20, 200] dB");
      if (n["seed"]) p.noise.seed = std::uint64_t(r.integer(n["seed"], "effects.noise.seed"));
      p.noise.enabled = true;
    }
    if (fx["support_damping"]) {
      const YAML::Node s = fx["support_damping"];
      r.check_keys(s, "effects.support_damping",
                   {"extra_decay_per_s", "per_mode_decay_per_s", "exponential_mean_per_s", "seed"});
      SupportDamping sd;
      if (s["extra_decay_per_s"])
        sd.extra_decay_per_s = r.non_negative(s["extra_decay_per_s"], "effects.support_damping.extra_decay_per_s");
      if (s["per_mode_decay_per_s"]) {
        sd.per_mode_decay_per_s = r.numbers(s["per_mode_decay_per_s"], "effects.support_damping.per_mode_decay_per_s");
        for (double v : sd.per_mode_decay_per_s)
          if (v < 0) r.fail(s["per_mode_decay_per_s"], "effects.support_damping.per_mode_decay_per_s", "must not be negative");
      }
      if (s["exponential_mean_per_s"])
        sd.exponential_mean_per_s = r.non_negative(s["exponential_mean_per_s"], "effects.support_damping.exponential_mean_per_s");
      if (s["seed"]) sd.seed = std::uint64_t(r.integer(s["seed"], "effects.support_damping.seed"));
      apply_support_damping(p.model, sd);
    }
    if (fx["doublets"]) {
      const YAML::Node d = fx["doublets"];
      r.check_keys(d, "effects.doublets", {"split_rel", "split_hz", "balance", "min_order"});
      Doublets db;
      // A doublet is one mode split a little by imperfection, into f -+ split/2: a split of f or more
      // would put the lower mode at or below f/2 (and at 2 f below 0 Hz).
      if (d["split_rel"]) {
        db.split_rel = r.positive(d["split_rel"], "effects.doublets.split_rel");
        if (db.split_rel >= 1.0)
          r.fail(d["split_rel"], "effects.doublets.split_rel",
                 "must lie in (0, 1): the two modes lie at f (1 -+ split_rel/2), got " + d["split_rel"].Scalar());
      }
      if (d["split_hz"]) db.split_hz = r.positive(d["split_hz"], "effects.doublets.split_hz");
      if (db.split_rel <= 0 && db.split_hz <= 0) r.fail(d, "effects.doublets", "needs split_rel or split_hz");
      if (d["balance"]) {
        db.balance = r.number(d["balance"], "effects.doublets.balance");
        if (!(db.balance >= 0 && db.balance <= 1)) r.fail(d["balance"], "effects.doublets.balance", "must lie in [0, 1]");
      }
      if (d["min_order"]) db.min_order = int(r.integer(d["min_order"], "effects.doublets.min_order"));
      if (db.split_hz > 0) {
        const double lowest = lowest_split_freq_hz(p.model, db, orders);
        if (db.split_hz >= lowest)
          r.fail(d["split_hz"], "effects.doublets.split_hz",
                 "must be less than the frequency of every mode it splits (the lowest is " + std::to_string(lowest) +
                     " Hz), got " + d["split_hz"].Scalar());
      }
      apply_doublets(p.model, db, orders);
    }
  }

  // Pruning sees the final model (after support damping and doublets): audibility depends on decay.
  if (root["prune"] && !p.model.modes.empty()) {
    const YAML::Node pr = root["prune"];
    r.check_keys(pr, "prune", {"method", "threshold_db", "playback_db", "combine", "order", "keep"});
    PruneOptions options;
    auto choice = [&](const char* key, auto parse, auto& out, const char* expected) {
      if (!pr[key]) return;
      const std::string path = std::string("prune.") + key;
      const auto v = parse(r.text(pr[key], path));
      if (!v) r.fail(pr[key], path, "unknown value '" + pr[key].Scalar() + "' (expected " + expected + ")");
      out = *v;
    };
    choice("method", parse_prune_method, options.method, "masking, naive, energy or loudness");
    choice("combine", parse_masking_combine, options.combine, "max or sum");
    choice("order", parse_mode_order, options.order, "naive, energy or loudness");
    if (pr["threshold_db"]) options.threshold_db = r.number(pr["threshold_db"], "prune.threshold_db");
    if (pr["playback_db"]) options.playback_db = r.number(pr["playback_db"], "prune.playback_db");
    std::size_t keep = p.model.modes.size();
    if (pr["keep"]) {
      const long long k = r.integer(pr["keep"], "prune.keep");
      if (k <= 0) r.fail(pr["keep"], "prune.keep", "must be at least 1");
      keep = std::size_t(k);
    }
    try {
      const PruneResult result = prune_modes(p.model, options);
      p.modes_before_pruning = p.model.modes.size();
      p.model = progressive_model(p.model, result, keep);
    } catch (const PruneError& e) {
      const YAML::Node field = pr[e.field()];
      if (e.mode() == PruneError::kNoMode)
        r.fail(field ? field : pr, "prune." + e.field(), e.problem());
      r.fail(pr, "prune", "mode " + std::to_string(e.mode()) + ": " + e.problem());
    }
  }

  if (root["level"]) {
    const YAML::Node l = root["level"];
    r.check_keys(l, "level", {"normalize", "target_dbfs", "attack_window_s"});
    p.level.mode = LevelMode::peak;
    if (l["normalize"]) {
      try {
        p.level.mode = parse_level_mode(r.text(l["normalize"], "level.normalize"));
      } catch (const std::invalid_argument& err) {
        r.fail(l["normalize"], "level.normalize", err.what());
      }
    }
    p.level.target_dbfs = p.level.mode == LevelMode::attack_rms ? -20.0 : -1.0;
    if (l["target_dbfs"]) {
      p.level.target_dbfs = r.number(l["target_dbfs"], "level.target_dbfs");
      if (p.level.target_dbfs > 0 || p.level.target_dbfs < -120)
        r.fail(l["target_dbfs"], "level.target_dbfs", "must lie in [-120, 0] dBFS");
    }
    if (l["attack_window_s"]) {
      p.level.attack_window_s = r.positive(l["attack_window_s"], "level.attack_window_s");
      if (p.level.attack_window_s > p.duration_s)
        r.fail(l["attack_window_s"], "level.attack_window_s", "longer than the sound");
    }
  } else {
    p.level.mode = LevelMode::peak;
    p.level.target_dbfs = -1.0;
  }
  if (root["output"]) {
    const YAML::Node o = root["output"];
    r.check_keys(o, "output", {"format"});
    if (o["format"]) {
      try {
        p.format = parse_sample_format(r.text(o["format"], "output.format"));
        p.format_where = r.where(o["format"], "output.format");
      } catch (const std::invalid_argument& err) {
        r.fail(o["format"], "output.format", err.what());
      }
    }
  }
  if (p.model.modes.empty()) r.fail(root, "", "the model has no modes");
  p.recipe_hash = sha256_hex(canonical_recipe(p));
  return p;
}

ParamSet load_paramset(const std::string& path, const std::vector<std::string>& overrides,
                       const Confinement* confinement) {
  const std::string text = read_bounded_file(path, kYamlFileLimit);
  const fs::path base = fs::path(path).has_parent_path() ? fs::path(path).parent_path() : fs::path(".");
  return parse_paramset(text, path, base.string(), overrides, confinement);
}

std::string canonical_recipe(const ParamSet& p) {
  std::string s;
  char buf[256];
  auto add = [&](const char* fmt, auto... v) {
    std::snprintf(buf, sizeof buf, fmt, v...);
    s += buf;
  };
  add("%s\n", kRendererVersion);
  add("sample_rate %.17g\nduration_s %.17g\n", p.sample_rate_hz, p.duration_s);
  add("excitation %s %.17g %.17g\n", to_string(p.excitation.shape).c_str(), p.excitation.contact_s,
      p.excitation.gain);
  add("level %s %.17g %.17g\n", to_string(p.level.mode).c_str(), p.level.target_dbfs,
      p.level.attack_window_s);
  add("format %s\n", to_string(p.format).c_str());
  if (p.noise.enabled) add("noise %.17g %llu\n", p.noise.snr_db, (unsigned long long)p.noise.seed);
  if (p.reverb.enabled)
    add("reverb %.17g %.17g %llu\n", p.reverb.rt60_s, p.reverb.level_db, (unsigned long long)p.reverb.seed);
  if (p.transient.enabled)
    add("transient %.17g %.17g %llu\n", p.transient.level_db, p.transient.duration_ms,
        (unsigned long long)p.transient.seed);
  add("modes %zu\n", p.model.modes.size());
  for (const Mode& m : p.model.modes)
    add("%.17g %.17g %.17g %.17g\n", m.freq_hz, m.decay_per_s, m.amp, m.phase_rad);
  return s;
}

}  // namespace ms
