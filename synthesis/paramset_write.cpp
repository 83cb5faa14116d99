// write_yaml: ParamSetRecipe -> YAML that read_recipe reads back to the same recipe.
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <utility>

#include "synthesis/exact_number.hpp"
#include "synthesis/paramset_recipe.hpp"

namespace ms {

namespace {

// One YAML document: block maps at the top, one flow map per section, numbers in their shortest exact form.
struct RecipeWriter {
  YAML::Emitter out;

  void key(const char* k) { out << YAML::Key << k << YAML::Value; }
  void number(const char* k, double v) {
    key(k);
    out << exact_number(v);
  }
  void integer(const char* k, long long v) {
    key(k);
    out << v;
  }
  void text(const char* k, const std::string& v) {
    key(k);
    out << v;
  }
  template <class Enum, std::size_t N>
  void name(const char* k, const NameTable<Enum, N>& names, Enum v) {
    text(k, std::string(enum_name(names, v)));
  }
  void numbers(const char* k, const std::vector<double>& v) {
    key(k);
    out << YAML::Flow << YAML::BeginSeq;
    for (double x : v) out << exact_number(x);
    out << YAML::EndSeq;
  }
  void begin_flow(const char* k) {
    key(k);
    out << YAML::Flow << YAML::BeginMap;
  }
  void end() { out << YAML::EndMap; }
  void seed(std::uint64_t s) { integer("seed", static_cast<long long>(s)); }  // as read: a signed integer
  // A noise effect: its numbers, then its seed.
  void seeded_noise(const char* k, std::initializer_list<std::pair<const char*, double>> fields, std::uint64_t s) {
    begin_flow(k);
    for (const auto& [field, value] : fields) number(field, value);
    seed(s);
    end();
  }

  void object(const ObjectRecipe& o);
  void modes(const ParamSetRecipe& r);
  void material(const ParamSetRecipe& r);
  void excitation(const Excitation& e);
  void effects(const ParamSetRecipe& r);
  void support_contacts(const SupportDamping& s);
  void prune(const PruneRecipe& p);
  void renderer(const ParamSetRecipe& r);
  void level(const OutputLevel& l);
};

void RecipeWriter::object(const ObjectRecipe& o) {
  const ObjectRecipe defaults;
  key("object");
  out << YAML::BeginMap;
  name("type", kObjectTypeNames, o.type);
  if (o.type == ObjectType::eigenvalues) {
    numbers("lambda0", o.lambda0);
    if (!o.gains.empty()) numbers("gains", o.gains);
  } else {
    const bool bar = o.type == ObjectType::bar;
    number(bar ? "length_m" : "radius_m", bar ? o.length_m : o.radius_m);
    number("thickness_m", o.thickness_m);
    if (!bar && o.poisson != defaults.poisson) number("poisson", o.poisson);
    if (bar && o.hit_position != defaults.hit_position) number("hit_position", o.hit_position);
    if (!bar && o.hit_radius != defaults.hit_radius) number("hit_radius", o.hit_radius);
    if (!o.hit_points.empty()) {
      begin_flow("hit_points");
      for (const HitPoint& h : o.hit_points) number(h.name.c_str(), h.position);
      end();
    }
  }
  if (o.max_modes != defaults.max_modes) integer("max_modes", static_cast<long long>(o.max_modes));
  out << YAML::EndMap;
}

void RecipeWriter::modes(const ParamSetRecipe& r) {
  if (!r.modes_csv.empty()) {
    text("modes", r.modes_csv);
  } else {
    key("modes");
    out << YAML::BeginSeq;
    for (const Mode& m : r.modes) {
      out << YAML::Flow << YAML::BeginMap;
      number("freq_hz", m.freq_hz);
      number("decay_per_s", m.decay_per_s);
      number("amp", m.amp);
      if (m.phase_rad != 0.0) number("phase_rad", m.phase_rad);
      end();
    }
    out << YAML::EndSeq;
  }
  if (r.hit_gains.empty()) return;
  key("hit_gains");
  out << YAML::BeginMap;
  for (const HitGains& h : r.hit_gains) numbers(h.name.c_str(), h.gains);
  out << YAML::EndMap;
}

void RecipeWriter::material(const ParamSetRecipe& r) {
  if (!r.material_file.empty()) {
    begin_flow("material");
    text("file", r.material_file);
    end();
  } else if (!r.material.empty()) {
    text("material", r.material);
  }
  if (r.damping_law != MaterialFit::rayleigh) name("damping_law", kMaterialFitNames, r.damping_law);
  if (r.damping) {
    const DampingLaw& d = *r.damping;
    begin_flow("damping");
    name("law", kDampingKindNames, d.kind);
    if (d.alpha1 != 0.0) number("alpha1", d.alpha1);
    if (d.alpha2 != 0.0) number("alpha2", d.alpha2);
    if (d.alpha3 != 1.0) number("alpha3", d.alpha3);
    if (d.loss_factor != 0.0 || d.kind == DampingKind::constant_q) number("loss_factor", d.loss_factor);
    if (d.relaxation_strength != 0.0) number("relaxation_strength", d.relaxation_strength);
    if (d.relaxation_hz != 0.0) number("relaxation_hz", d.relaxation_hz);
    end();
  }
  if (r.specific_modulus_m2_s2) number("specific_modulus_m2_s2", *r.specific_modulus_m2_s2);
  if (r.fundamental_hz) number("fundamental_hz", *r.fundamental_hz);
}

void RecipeWriter::excitation(const Excitation& e) {
  begin_flow("excitation");
  name("type", kPulseShapeNames, e.shape);
  if (e.shape != PulseShape::impulse) number("contact_s", e.contact_s);
  if (e.gain != 1.0) number("gain", e.gain);
  end();
}

void RecipeWriter::effects(const ParamSetRecipe& r) {
  if (!r.support_damping && !r.doublets && !r.noise.enabled && !r.room.enabled && !r.reverb.enabled && !r.transient.enabled) return;
  key("effects");
  out << YAML::BeginMap;
  if (const auto& s = r.support_damping) {
    begin_flow("support_damping");
    if (s->extra_decay_per_s != 0.0) number("extra_decay_per_s", s->extra_decay_per_s);
    if (!s->per_mode_decay_per_s.empty()) numbers("per_mode_decay_per_s", s->per_mode_decay_per_s);
    if (s->exponential_mean_per_s != 0.0) number("exponential_mean_per_s", s->exponential_mean_per_s);
    if (s->seed != 0) seed(s->seed);
    if (!s->contacts.empty()) support_contacts(*s);
    end();
  }
  if (const auto& d = r.doublets) {
    const Doublets defaults;
    begin_flow("doublets");
    if (d->split_rel != 0.0) number("split_rel", d->split_rel);
    if (d->split_hz != 0.0) number("split_hz", d->split_hz);
    if (d->balance != defaults.balance) number("balance", d->balance);
    if (d->min_order != defaults.min_order) integer("min_order", d->min_order);
    end();
  }
  if (r.noise.enabled) seeded_noise("noise", {{"snr_db", r.noise.snr_db}}, r.noise.seed);
  if (r.room.enabled) {
    begin_flow("room");
    if (r.room.rt60_s.size() == 1)
      number("rt60_s", r.room.rt60_s[0]);
    else
      numbers("rt60_s", r.room.rt60_s);
    number("drr_db", r.room.drr_db);
    seed(r.room.seed);
    end();
  }
  if (r.reverb.enabled)
    seeded_noise("reverb", {{"rt60_s", r.reverb.rt60_s}, {"level_db", r.reverb.level_db}}, r.reverb.seed);
  if (r.transient.enabled && (r.transient.band_limited() || r.transient.hold_ms > 0.0)) {
    begin_flow("transient");
    number("level_db", r.transient.level_db);
    number("duration_ms", r.transient.duration_ms);
    if (r.transient.band_limited()) numbers("band_hz", {r.transient.low_hz, r.transient.high_hz});
    if (r.transient.hold_ms > 0.0) number("hold_ms", r.transient.hold_ms);
    seed(r.transient.seed);
    end();
  } else if (r.transient.enabled) {
    seeded_noise("transient", {{"level_db", r.transient.level_db}, {"duration_ms", r.transient.duration_ms}},
                 r.transient.seed);
  }
  out << YAML::EndMap;
}

// A contact without its own c and with the normal along the displacement is its position alone.
void RecipeWriter::support_contacts(const SupportDamping& s) {
  key("contacts");
  out << YAML::Flow << YAML::BeginSeq;
  for (const SupportContact& c : s.contacts) {
    if (!c.c_per_s && c.normal_deg == 0.0) {
      out << exact_number(c.position);
      continue;
    }
    out << YAML::Flow << YAML::BeginMap;
    number("position", c.position);
    if (c.c_per_s) number("c", *c.c_per_s);
    if (c.normal_deg != 0.0) number("normal_deg", c.normal_deg);
    end();
  }
  out << YAML::EndSeq;
  number("mu", s.mu);
  if (s.c_per_s) number("c", *s.c_per_s);
}

void RecipeWriter::prune(const PruneRecipe& p) {
  const PruneOptions defaults;
  begin_flow("prune");
  name("method", kPruneMethodNames, p.options.method);
  if (p.options.threshold_db != defaults.threshold_db) number("threshold_db", p.options.threshold_db);
  if (p.options.playback_db != defaults.playback_db) number("playback_db", p.options.playback_db);
  if (p.options.combine != defaults.combine) name("combine", kMaskingCombineNames, p.options.combine);
  if (p.options.order != defaults.order) name("order", kModeOrderNames, p.options.order);
  if (p.keep) integer("keep", static_cast<long long>(*p.keep));
  end();
}

void RecipeWriter::renderer(const ParamSetRecipe& r) {
  if (r.phase != OnsetPhase::sine) name("phase", kOnsetPhaseNames, r.phase);
  if (r.renderer == Renderer::resonator) return;
  name("renderer", kRendererNames, r.renderer);
  const BandpassRecipe& b = *r.bandpass;
  begin_flow("bandpass");
  if (b.material) {
    name("material", kBandpassMaterialNames, *b.material);
    if (b.q_table != QTable::table_4_1) name("q_table", kQTableNames, b.q_table);
  } else if (b.q.size() == 1) {
    number("q", b.q[0]);
  } else {
    numbers("q", b.q);
  }
  if (b.clip != 1.0) number("clip", b.clip);
  end();
}

void RecipeWriter::level(const OutputLevel& l) {
  begin_flow("level");
  name("normalize", kLevelModeNames, l.mode);
  if (l.target_dbfs != default_target_dbfs(l.mode)) number("target_dbfs", l.target_dbfs);
  if (l.attack_window_s != OutputLevel{}.attack_window_s) number("attack_window_s", l.attack_window_s);
  end();
}

}  // namespace

std::string write_yaml(const ParamSetRecipe& r) {
  RecipeWriter w;
  w.out << YAML::BeginMap;
  if (!r.description.empty()) w.text("description", r.description);
  w.number("sample_rate", r.sample_rate_hz);
  w.number("duration_s", r.duration_s);
  if (r.object) {
    w.object(*r.object);
    w.material(r);
  } else {
    w.modes(r);
  }
  if (r.amp_scale) w.number("amp_scale", *r.amp_scale);
  if (r.stiffness_scale != 1.0) w.number("stiffness_scale", r.stiffness_scale);
  if (r.size_scale != 1.0) w.number("size_scale", r.size_scale);
  if (!r.hit.empty()) w.text("hit", r.hit);
  w.excitation(r.excitation);
  w.effects(r);
  if (r.prune) w.prune(*r.prune);
  if (r.residual) {
    w.begin_flow("residual");
    w.text("file", r.residual->file);
    if (r.residual->gain_db != 0.0) w.number("gain_db", r.residual->gain_db);
    if (r.residual->seed != 0) w.seed(r.residual->seed);
    w.end();
  }
  w.renderer(r);
  w.level(r.level);
  w.begin_flow("output");
  w.name("format", kSampleFormatNames, r.format);
  w.end();
  w.out << YAML::EndMap;
  return std::string(w.out.c_str()) + "\n";
}

}  // namespace ms
