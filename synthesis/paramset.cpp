// resolve: ParamSetRecipe -> ParamSet (materials looked up, modes built, effects, pruning, level, hash).
#include "synthesis/paramset.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>

#include "synthesis/bounded_file.hpp"
#include "synthesis/contact_damping.hpp"
#include "synthesis/csv.hpp"
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
constexpr std::size_t kMaxModes = 200000;

// An object's eigenvalues (for E/rho = 1), circumferential orders and gains at each hit point.
struct ObjectSpec {
  std::vector<double> lambda0;
  std::vector<int> orders;
  std::vector<std::string> hit_names;
  std::vector<std::vector<double>> hit_gains;
  std::vector<std::vector<double>> contact_shapes;  // [k][n]: mode shape n at contact k
};

// The object's modes up to max_lambda0_of_unit, or (unit_scale_unknown) only its first mode; the mode
// shapes at the hit points and at `contacts` (bar, plate).
ObjectSpec object_spec(const ObjectRecipe& o, double max_lambda0_of_unit, bool unit_scale_unknown,
                       const std::vector<SupportContact>& contacts = {}) {
  ObjectSpec spec;
  if (o.type == ObjectType::eigenvalues) {
    spec.lambda0 = o.lambda0;
    spec.orders.assign(o.lambda0.size(), 0);
    spec.hit_names = {"default"};
    spec.hit_gains = {o.gains.empty() ? std::vector<double>(o.lambda0.size(), 1.0) : o.gains};
    return spec;
  }
  const bool bar = o.type == ObjectType::bar;
  spec.hit_names = {"default"};
  std::vector<double> positions = {bar ? o.hit_position : o.hit_radius};
  for (const HitPoint& h : o.hit_points) {
    spec.hit_names.push_back(h.name);
    positions.push_back(h.position);
  }
  for (const SupportContact& c : contacts) positions.push_back(c.position);
  const std::size_t max_modes = unit_scale_unknown ? 1 : o.max_modes;
  ObjectModes om;
  if (bar) {
    const double limit = unit_scale_unknown ? free_free_bar(o.length_m, o.thickness_m, {}, 1e300, 1).lambda0[0] * 1.0001
                                            : max_lambda0_of_unit;
    om = free_free_bar(o.length_m, o.thickness_m, positions, limit, max_modes);
  } else {
    // The fundamental of a free plate is the (2 nodal diameters, 0 circles) mode.
    const double k0 = free_plate_roots(2, o.poisson, 4.0).at(0);
    const double stiff = o.thickness_m * o.thickness_m / (12.0 * (1.0 - o.poisson * o.poisson));
    const double first = std::pow(k0, 4) * stiff / std::pow(o.radius_m, 4);
    const double limit = unit_scale_unknown ? first * 1.0001 : max_lambda0_of_unit;
    om = free_circular_plate(o.radius_m, o.thickness_m, o.poisson, positions, limit, max_modes);
  }
  spec.lambda0 = om.lambda0;
  spec.orders = om.circumferential_order;
  spec.hit_gains.assign(om.gains.begin(), om.gains.begin() + std::ptrdiff_t(spec.hit_names.size()));
  spec.contact_shapes.assign(om.gains.begin() + std::ptrdiff_t(spec.hit_names.size()), om.gains.end());
  return spec;
}

// A file the set names, relative to the set's folder; it must lie inside `confinement` (without one,
// inside paramset_confinement of that folder).
fs::path confined_file(const RecipeOrigin& origin, const std::string& written, const std::string& key_path,
                       const Confinement* confinement) {
  const Confinement own = confinement ? Confinement::anywhere() : paramset_confinement(origin.base_dir);
  const Confinement& allowed = confinement ? *confinement : own;
  if (const std::string problem = allowed.problem(written, origin.base_dir); !problem.empty())
    origin.fail(key_path, problem);
  fs::path file(written);
  if (file.is_relative()) file = fs::path(origin.base_dir) / file;
  return file;
}

// Reads a file the set names; its own located errors pass through, others name the key.
template <class Read>
auto read_named_file(const RecipeOrigin& origin, const fs::path& file, const std::string& key_path, Read read) {
  try {
    return read(file.string());
  } catch (const InputError& e) {
    if (e.where().line > 0) throw;
    origin.fail(key_path, "cannot use '" + file.string() + "': " + e.problem());
  }
}

std::size_t hit_index(const RecipeOrigin& origin, const std::string& hit, const std::vector<std::string>& names) {
  const auto it = std::find(names.begin(), names.end(), hit);
  if (it == names.end()) {
    const std::string near = nearest_key(hit, names);
    origin.fail("hit", "unknown hit point '" + hit + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
  }
  return std::size_t(it - names.begin());
}

// Inline modes or a modes CSV, scaled, with their named hit gains.
ModalModel listed_modes(const ParamSetRecipe& r, const Confinement* confinement) {
  ModalModel model;
  if (!r.modes_csv.empty()) {
    const fs::path csv = confined_file(r.origin, r.modes_csv, "modes", confinement);
    model = read_named_file(r.origin, csv, "modes", [](const std::string& path) {
      return parse_modes_csv(read_bounded_file(path, kCsvFileLimit), path);
    });
  } else {
    model.modes = r.modes;
  }
  // Uniform size scaling and stiffness scaling move frequencies: f * sqrt(stiffness) / size.
  const double fscale = std::sqrt(r.stiffness_scale) / r.size_scale;
  for (Mode& m : model.modes) {
    m.freq_hz *= fscale;
    m.amp *= r.amp_scale.value_or(1.0);
  }
  for (const HitGains& h : r.hit_gains) {
    if (h.gains.size() != model.modes.size())
      r.origin.fail("hit_gains." + h.name, "needs one gain per mode (" + std::to_string(model.modes.size()) + ")");
    model.hit_point_names.push_back(h.name);
    model.hit_gains.push_back(h.gains);
  }
  if (model.modes.size() > kMaxModes)
    r.origin.fail("", "too many modes (" + std::to_string(model.modes.size()) + " > 200000)");
  if (!r.hit.empty()) model.modes = at_hit_point(model, hit_index(r.origin, r.hit, model.hit_point_names)).modes;
  return model;
}

// The material `material:` names: a library id or a material file (nullopt when none).
std::optional<Material> named_material(const ParamSetRecipe& r, const Confinement* confinement) {
  if (!r.material_file.empty()) {
    const fs::path file = confined_file(r.origin, r.material_file, "material.file", confinement);
    return read_named_file(r.origin, file, "material.file", [](const std::string& path) { return read_material_file(path); });
  }
  if (r.material.empty()) return std::nullopt;
  if (const Material* m = find_material(r.material)) return *m;
  const std::string near = nearest_key(r.material, material_ids());
  r.origin.fail("material", "unknown material '" + r.material + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
}

// `residual: {file: X}`: a residual file (residual_file.hpp), relative to the set's folder and inside its
// confinement like a modes CSV, made at the set's sample rate; its bytes' digest enters the hash.
ResidualUse read_residual(const ParamSetRecipe& r, const Confinement* confinement) {
  const fs::path file = confined_file(r.origin, r.residual->file, "residual.file", confinement);
  ResidualUse use;
  const std::string bytes = read_named_file(r.origin, file, "residual.file", [](const std::string& path) {
    return read_bounded_file(path, kResidualFileLimit);
  });
  use.spectrogram = std::make_shared<const ResidualSpectrogram>(parse_residual_file(bytes, file.string()));
  if (use.spectrogram->sample_rate_hz != r.sample_rate_hz)
    r.origin.fail("residual.file", "'" + file.string() + "' was made at " + csv::number(use.spectrogram->sample_rate_hz) +
                                       " Hz, the set renders at " + csv::number(r.sample_rate_hz) + " Hz");
  use.sha256 = sha256_hex(bytes);
  use.gain_db = r.residual->gain_db;
  use.seed = r.residual->seed;
  return use;
}

DampingLaw object_law(const ParamSetRecipe& r, const std::optional<Material>& material) {
  if (r.damping) return *r.damping;
  if (!material) r.origin.fail("", "an 'object' model needs a 'material' or a 'damping' law");
  if (r.damping_law == MaterialFit::rayleigh) return material->rayleigh;
  if (!material->hybrid) r.origin.fail("damping_law", material->id + " has no hybrid fit");
  return *material->hybrid;
}

// The decay support_damping's contacts add to each of the object's modes `kept` (indices into spec).
std::vector<double> recipe_contact_decay(const SupportDamping& support, const ObjectSpec& spec,
                                         const std::vector<std::size_t>& kept) {
  std::vector<std::vector<double>> shapes;
  std::vector<double> c_per_s, normal_deg;
  for (std::size_t k = 0; k < support.contacts.size(); ++k) {
    std::vector<double>& shape = shapes.emplace_back();
    for (std::size_t i : kept) shape.push_back(spec.contact_shapes[k][i]);
    c_per_s.push_back(support.contacts[k].c_per_s.value_or(support.c_per_s.value_or(0.0)));
    normal_deg.push_back(support.contacts[k].normal_deg);
  }
  return contact_decay_per_s(shapes, c_per_s, normal_deg, support.mu, kept.size());
}

// An object's modes below Nyquist, with the circumferential order of each (for doublets) and the decay
// support_damping's contacts add to each.
ModalModel object_modes(const ParamSetRecipe& r, const Confinement* confinement, std::vector<int>& orders,
                        std::vector<double>& contact_decay, std::vector<std::string>& warnings) {
  const std::optional<Material> material = named_material(r, confinement);
  const DampingLaw law = object_law(r, material);
  const double gamma = r.specific_modulus_m2_s2.value_or(material ? material->specific_modulus_m2_s2 : 0.0);
  if (gamma <= 0.0 && !r.fundamental_hz)
    r.origin.fail("", "give 'specific_modulus_m2_s2' (E/rho) or 'fundamental_hz' for the stiffness");
  const double amp_scale = r.amp_scale.value_or(material ? material->amp_scale : 1.0);
  const double nyquist = 0.5 * r.sample_rate_hz;
  double scale = gamma * r.stiffness_scale / (r.size_scale * r.size_scale);  // lambda = scale * lambda0
  if (r.fundamental_hz)
    scale = std::pow(2.0 * std::numbers::pi * *r.fundamental_hz, 2) / object_spec(*r.object, 0.0, true).lambda0.at(0);
  const double max_lambda0 = std::pow(2.0 * std::numbers::pi * nyquist, 2) * 1.2 / scale;  // damping lowers f
  const ObjectSpec spec = object_spec(*r.object, max_lambda0, false,
                                      r.support_damping ? r.support_damping->contacts : std::vector<SupportContact>{});
  // The hit point sets the amplitudes: the mode shapes at that point.
  const std::size_t hit = r.hit.empty() ? 0 : hit_index(r.origin, r.hit, spec.hit_names);
  std::size_t overdamped = 0;
  ModalModel model = modes_from_eigenvalues(spec.lambda0, law, scale, amp_scale, spec.hit_gains[hit], &overdamped);
  if (overdamped > 0) warnings.push_back(std::to_string(overdamped) + " overdamped mode(s) dropped");
  // Keep the circumferential orders (and the contacts' shapes) aligned with the surviving modes.
  std::vector<std::size_t> sounding;
  for (std::size_t i = 0; i < spec.lambda0.size(); ++i) {
    const double lambda = scale * spec.lambda0[i], d = law.decay_per_s(lambda);
    if (lambda - d * d > 0) sounding.push_back(i);
  }
  // An analytic object has infinitely many modes: truncate the series at Nyquist (no warning;
  // only modes a person listed explicitly warn when they cannot sound).
  std::vector<Mode> below;
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < model.modes.size(); ++i)
    if (model.modes[i].freq_hz < nyquist) {
      below.push_back(model.modes[i]);
      kept.push_back(sounding[i]);
      orders.push_back(spec.orders[sounding[i]]);
    }
  model.modes = std::move(below);
  if (r.support_damping && !r.support_damping->contacts.empty())
    contact_decay = recipe_contact_decay(*r.support_damping, spec, kept);
  if (model.modes.size() > kMaxModes)
    r.origin.fail("", "too many modes (" + std::to_string(model.modes.size()) + " > 200000)");
  return model;
}

void apply_recipe_doublets(const ParamSetRecipe& r, ModalModel& model, const std::vector<int>& orders) {
  const Doublets& db = *r.doublets;
  if (db.split_hz > 0) {
    const double lowest = lowest_split_freq_hz(model, db, orders);
    if (db.split_hz >= lowest)
      r.origin.fail("effects.doublets.split_hz", "must be less than the frequency of every mode it splits (the lowest is " +
                                                     std::to_string(lowest) + " Hz), got " + csv::number(db.split_hz));
  }
  apply_doublets(model, db, orders);
}

// Pruning sees the final model (after support damping and doublets): audibility depends on decay.
void apply_recipe_prune(const ParamSetRecipe& r, ParamSet& p) {
  const PruneRecipe& pr = *r.prune;
  try {
    const PruneResult result = prune_modes(p.model, pr.options);
    p.modes_before_pruning = p.model.modes.size();
    p.model = progressive_model(p.model, result, pr.keep.value_or(p.model.modes.size()));
  } catch (const PruneError& e) {
    const std::string field = "prune." + e.field();
    if (e.mode() != PruneError::kNoMode) r.origin.fail("prune", "mode " + std::to_string(e.mode()) + ": " + e.problem());
    const auto written = r.origin.written_at.find(field);
    throw InputError(written != r.origin.written_at.end() ? written->second : r.origin.where("prune"),
                     field + ": " + e.problem());
  }
}

// renderer: bandpass: the filters' Q, one for all or one per mode of the resolved model, and the clipper.
void apply_recipe_bandpass(const ParamSetRecipe& r, ParamSet& p) {
  p.renderer = Renderer::bandpass;
  p.bandpass_q = bandpass_q(*r.bandpass);
  p.bandpass_clip = r.bandpass->clip;
  const std::size_t n = p.bandpass_q.size(), modes = p.model.modes.size();
  if (n != 1 && n != modes)
    r.origin.fail("bandpass.q", std::to_string(n) + " Q values for " + std::to_string(modes) +
                                    " modes (after doublets and pruning): give one Q, or one per mode");
}

}  // namespace

ParamSet resolve(const ParamSetRecipe& r, const Confinement* confinement) {
  ParamSet p;
  p.source = r.origin.file;
  p.description = r.description;
  p.sample_rate_hz = r.sample_rate_hz;
  p.duration_s = r.duration_s;
  p.excitation = r.excitation;
  p.level = r.level;
  p.room = r.room;
  p.reverb = r.reverb;
  p.transient = r.transient;
  p.noise = r.noise;
  p.format = r.format;
  const auto format_at = r.origin.written_at.find("output.format");
  p.format_where = format_at != r.origin.written_at.end() ? format_at->second : SourceLocation{r.origin.file, 0, 0};
  std::vector<int> orders;
  std::vector<double> contact_decay;  // per mode, from support_damping's contacts
  p.model = r.object ? object_modes(r, confinement, orders, contact_decay, p.warnings) : listed_modes(r, confinement);
  if (r.phase == OnsetPhase::cosine)
    for (Mode& m : p.model.modes) m.phase_rad += 0.5 * std::numbers::pi;  // sin(x + pi/2) = cos x
  if (r.support_damping) apply_support_damping(p.model, *r.support_damping);
  for (std::size_t i = 0; i < contact_decay.size(); ++i) p.model.modes[i].decay_per_s += contact_decay[i];
  if (r.doublets) apply_recipe_doublets(r, p.model, orders);
  if (r.prune && !p.model.modes.empty()) apply_recipe_prune(r, p);
  if (p.model.modes.empty()) r.origin.fail("", "the model has no modes");
  if (r.renderer == Renderer::bandpass) apply_recipe_bandpass(r, p);
  if (r.residual) p.residual = read_residual(r, confinement);
  p.recipe_hash = sha256_hex(canonical_recipe(p));
  return p;
}

ParamSet parse_paramset(const std::string& yaml_text, const std::string& file, const std::string& base_dir,
                        const std::vector<std::string>& overrides, const Confinement* confinement) {
  return resolve(read_recipe(yaml_text, file, base_dir, overrides), confinement);
}

ParamSet load_paramset(const std::string& path, const std::vector<std::string>& overrides,
                       const Confinement* confinement) {
  return resolve(read_recipe_file(path, overrides), confinement);
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
  if (p.room.enabled) {
    s += "room";
    for (double t : p.room.rt60_s) add(" %.17g", t);
    add(" %.17g %llu\n", p.room.drr_db, (unsigned long long)p.room.seed);
  }
  if (p.reverb.enabled)
    add("reverb %.17g %.17g %llu\n", p.reverb.rt60_s, p.reverb.level_db, (unsigned long long)p.reverb.seed);
  if (p.transient.enabled)
    add("transient %.17g %.17g %llu\n", p.transient.level_db, p.transient.duration_ms,
        (unsigned long long)p.transient.seed);
  if (p.transient.enabled && p.transient.band_limited())
    add("transient_band %.17g %.17g\n", p.transient.low_hz, p.transient.high_hz);
  if (p.transient.enabled && p.transient.hold_ms > 0.0) add("transient_hold %.17g\n", p.transient.hold_ms);
  if (p.residual.spectrogram)
    add("residual %s %.17g %llu\n", p.residual.sha256.c_str(), p.residual.gain_db, (unsigned long long)p.residual.seed);
  if (p.renderer == Renderer::bandpass) {
    add("bandpass %.17g", p.bandpass_clip);
    for (double q : p.bandpass_q) add(" %.17g", q);
    add("\n");
  }
  add("modes %zu\n", p.model.modes.size());
  for (const Mode& m : p.model.modes)
    add("%.17g %.17g %.17g %.17g\n", m.freq_hz, m.decay_per_s, m.amp, m.phase_rad);
  return s;
}

}  // namespace ms
