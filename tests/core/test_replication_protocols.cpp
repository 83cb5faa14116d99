// The shipped replication protocols (protocols/*.yaml other than demo): each validates with no
// problem, and each keeps the design numbers of the paper it replicates (see its header comment).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/schedule.hpp"
#include "support/test_util.hpp"
#include "synthesis/paramset.hpp"

namespace {

const std::vector<std::string> kReplications = {"vandendoel2002", "sterling2019", "sterling2019_handtuning",
                                                "ren2013_materials", "ab_synthesis_methods",
                                                "skandalou2017_variation"};

std::string protocol_path(const std::string& name) {
  return std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/" + name + ".yaml";
}

ms::Protocol load(const std::string& name) {
  std::vector<std::string> problems;
  ms::Protocol p = ms::load_protocol(protocol_path(name), &problems);
  EXPECT_TRUE(problems.empty()) << name << ": " << (problems.empty() ? "" : problems.front());
  return p;
}

const ms::Block& block(const ms::Protocol& p, const std::string& id) {
  const auto it = std::find_if(p.blocks.begin(), p.blocks.end(), [&](const ms::Block& b) { return b.id == id; });
  if (it == p.blocks.end()) throw std::runtime_error("no block '" + id + "' in " + p.file);
  return *it;
}

// Test trials (not training) of one block in a participant's schedule.
std::vector<ms::Trial> trials_of(const ms::Schedule& s, const std::string& block_id) {
  std::vector<ms::Trial> out;
  for (const auto& t : s.trials)
    if (t.block_id == block_id) out.push_back(t);
  return out;
}

std::vector<std::string> names(const std::vector<ms::StimulusRef>& refs) {
  std::vector<std::string> out;
  for (const auto& r : refs) out.push_back(r.name);
  return out;
}

TEST(ReplicationProtocols, EachValidatesWithNoProblem) {
  for (const auto& name : kReplications) {
    const ms::ProtocolCheck check = ms::check_protocol_file(protocol_path(name));
    std::string all;
    for (const auto& p : check.problems) all += p + "\n";
    EXPECT_TRUE(check.problems.empty()) << all;
    EXPECT_TRUE(check.protocol.has_value()) << name;
  }
}

// van den Doel et al. 2002: a descending a_v series (method of limits) from 20 dB in -1 dB steps against
// the unpruned model, one per object and listener; the adaptive token procedure over every token of
// each sequence (one series per object x order); magnitude estimation of every pair of 11 tokens + the
// reference.
TEST(ReplicationProtocols, VanDenDoel2002KeepsThePapersDesign) {
  const ms::Protocol p = load("vandendoel2002");
  // The paper's 22.05 kHz (section 3): the protocol and every parameter set it renders (the check
  // refuses a set at another rate than the protocol's).
  EXPECT_EQ(p.sample_rate_hz, 22050.0);
  for (const ms::StimulusSource& s : p.stimuli)
    if (s.kind == ms::StimulusKind::paramset)
      EXPECT_EQ(ms::load_paramset(std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/" + s.path).sample_rate_hz, 22050.0)
          << s.name;
  for (const std::string object : {"vase", "bowl"}) {
    const ms::Block& b = block(p, "av-" + object);
    const auto& s = std::get<ms::LimitsBlock>(b.body);
    EXPECT_EQ(s.parameter, "prune.threshold_db");
    EXPECT_DOUBLE_EQ(s.start, 20.0);
    EXPECT_DOUBLE_EQ(s.step, -1.0);  // "reduced by 1dB for every pair"
    EXPECT_EQ(s.stimulus.name, object + "-av");
    ASSERT_TRUE(s.reference.has_value());
    EXPECT_EQ(s.reference->name, object + "-full");  // Y: all modes
    EXPECT_EQ(b.repeats, 1);  // Table 1: one value per listener and object
  }
  const ms::Schedule schedule = ms::make_schedule(p, "P01");
  for (const std::string object : {"vase", "bowl"})
    for (const std::string method : {"naive", "energy"}) {
      const auto& g = std::get<ms::MagnitudeBlock>(block(p, "dissimilarity-" + object + "-" + method).body);
      ASSERT_TRUE(g.modulus.has_value());
      EXPECT_EQ((*g.modulus)[0].name, object + "-full");  // the standard pair: reference and one mode
      EXPECT_EQ((*g.modulus)[1].name, object + (method == "naive" ? "-n1" : "-e1"));
      EXPECT_TRUE(g.all_pairs);
      EXPECT_EQ(g.stimuli.size(), 12u);  // 11 tokens + the reference
      const auto trials = trials_of(schedule, "dissimilarity-" + object + "-" + method);
      EXPECT_EQ(trials.size(), 78u);  // C(12, 2) distinct + 12 identical pairs, as in the paper
      std::set<std::set<std::string>> distinct;
      std::size_t identical = 0;
      for (const auto& t : trials) {
        distinct.insert({t.stimuli[0], t.stimuli[1]});
        identical += t.stimuli[0] == t.stimuli[1];
      }
      EXPECT_EQ(distinct.size(), 78u);
      EXPECT_EQ(identical, 12u);

      // Exp. 2: every token of the sequence, from the one with the most modes down to one mode.
      const ms::Block& tb = block(p, "tokens-" + object + "-" + method);
      const auto& tokens = std::get<ms::TokensBlock>(tb.body);
      EXPECT_EQ(tokens.stimulus.name, object + "-" + method);
      EXPECT_EQ(tokens.to, 1);
      EXPECT_EQ(tb.repeats, 1);  // Table 2: one count per listener and sequence
      EXPECT_EQ(trials_of(schedule, tb.id).size(), 1u);
    }
  // The ceilings: every mode in the naive order (the paper's 179 and 128), the audible ones at a_v = 16
  // dB in the energy order (the paper's 100 and 41; 132 and 103 on the stand-ins).
  const std::map<std::string, int> from{{"tokens-vase-naive", 179}, {"tokens-vase-energy", 132},
                                        {"tokens-bowl-naive", 128}, {"tokens-bowl-energy", 103}};
  for (const auto& [id, n] : from) EXPECT_EQ(std::get<ms::TokensBlock>(block(p, id).body).from, n) << id;
  // The validator refuses a ceiling above what the pruning keeps, so these are the sequences' full lengths.
  EXPECT_TRUE(ms::check_protocol_file(protocol_path("vandendoel2002")).problems.empty());
}

// Sterling et al. 2019: 4 datasets x 2 shapes x 5 materials; shape and material identification;
// duration, ringiness, tonality and pitch on 7-point scales (tonality: mixed tones .. pure tone).
TEST(ReplicationProtocols, Sterling2019KeepsThePapersDesign) {
  const ms::Protocol p = load("sterling2019");
  const auto& material = std::get<ms::IdentifyBlock>(block(p, "material").body);
  EXPECT_EQ(material.labels, (std::vector<std::string>{"wood", "metal", "plastic", "glass", "porcelain"}));
  EXPECT_EQ(material.stimuli.size(), 40u);
  std::set<std::string> datasets, shapes, materials;
  for (const auto& s : names(material.stimuli)) {
    const auto a = s.find('-'), b = s.find('-', a + 1);
    datasets.insert(s.substr(0, a));
    shapes.insert(s.substr(a + 1, b - a - 1));
    materials.insert(s.substr(b + 1));
  }
  EXPECT_EQ(datasets.size(), 4u);
  EXPECT_EQ(shapes, (std::set<std::string>{"disc", "rod"}));
  EXPECT_EQ(materials.size(), 5u);
  const auto& shape = std::get<ms::IdentifyBlock>(block(p, "shape").body);
  EXPECT_EQ(shape.labels, (std::vector<std::string>{"disc", "rod"}));
  EXPECT_EQ(names(shape.stimuli), names(material.stimuli));

  const auto& ratings = std::get<ms::RatingBlock>(block(p, "ratings").body);
  EXPECT_EQ(names(ratings.stimuli), names(material.stimuli));
  std::vector<std::string> attributes;
  for (const auto& a : ratings.attributes) {
    attributes.push_back(a.name);
    EXPECT_EQ(a.points, 7) << a.name;
    EXPECT_FALSE(a.low.empty() || a.high.empty()) << a.name;
    if (a.name == "tonality") {
      EXPECT_EQ(a.low, "mixed tones");
      EXPECT_EQ(a.high, "pure tone");
    }
  }
  EXPECT_EQ(attributes, (std::vector<std::string>{"duration", "ringiness", "tonality", "pitch"}));
  const ms::Schedule s = ms::make_schedule(p, "P01");
  EXPECT_EQ(trials_of(s, "material").size() + trials_of(s, "shape").size() + trials_of(s, "ratings").size(), 120u);
}

// Sterling et al. 2019, section 1.3.2: a training object, then six discs in random order, in two sections:
// three parameters (Rayleigh alpha1, alpha2, gamma = E/rho) and two (alpha1, alpha2). Each target states
// the parameters behind it (`truth:`, what adjust.csv's truth column carries), they are the ones the
// target is rendered with, and each lies inside its slider's range but away from its middle (where the
// slider starts).
TEST(ReplicationProtocols, Sterling2019HandTuningKeepsThePapersDesign) {
  const ms::Protocol p = load("sterling2019_handtuning");
  const std::vector<std::string> objects = {"porcelain", "travertine", "wood", "steel", "plastic", "glass"};
  for (const std::string section : {"three", "two"}) {
    const std::vector<std::string> keys =
        section == "three" ? std::vector<std::string>{"damping.alpha1", "damping.alpha2", "specific_modulus_m2_s2"}
                           : std::vector<std::string>{"damping.alpha1", "damping.alpha2"};
    const ms::Block& training = block(p, "training-" + section);
    EXPECT_TRUE(training.training);
    EXPECT_EQ(std::get<ms::AdjustBlock>(training.body).target->name, "target-cymbal");
    for (const std::string& object : objects) {
      const ms::Block& b = block(p, section + "-" + object);
      EXPECT_FALSE(b.training);
      EXPECT_EQ(b.shuffle, section);  // the six in an order drawn per participant
      const auto& adjust = std::get<ms::AdjustBlock>(b.body);
      ASSERT_TRUE(adjust.target.has_value());
      const ms::StimulusSource* target = p.find_stimulus(adjust.target->name);
      ASSERT_NE(target, nullptr);
      std::map<std::string, std::string> truth(target->truth.begin(), target->truth.end()), rendered;
      for (const std::string& o : target->overrides) rendered[o.substr(0, o.find('='))] = o.substr(o.find('=') + 1);
      std::vector<std::string> slider_keys;
      for (const ms::Slider& sl : adjust.sliders) {
        slider_keys.push_back(sl.key);
        ASSERT_EQ(truth.count(sl.key), 1u) << object << " " << sl.key;
        EXPECT_EQ(std::stod(truth.at(sl.key)), std::stod(rendered.at(sl.key))) << object << " " << sl.key;
        const double position = (std::stod(truth.at(sl.key)) - sl.min) / (sl.max - sl.min);
        EXPECT_GT(position, 0.15) << object << " " << sl.key;
        EXPECT_LT(position, 0.85) << object << " " << sl.key;
        EXPECT_GT(std::abs(position - 0.5), 0.1) << object << " " << sl.key;
      }
      EXPECT_EQ(slider_keys, keys) << object;
    }
  }
  const auto order = [&](const std::string& participant) {
    std::vector<std::string> blocks;
    for (const auto& t : ms::make_schedule(p, participant).trials)
      if (t.block_id.rfind("three-", 0) == 0) blocks.push_back(t.block_id);
    return blocks;
  };
  EXPECT_EQ(order("P01").size(), 6u);
  EXPECT_NE(order("P01"), order("P02"));
}

// Ren et al. 2013: 16 synthesised clips (3 shapes x 4 materials + 4 glass bowls) and the recorded
// condition, 6 real recordings (two each of metal, wood and glass) in the same series; five labels; the
// plates are named as their label so the plate confusion matrix reads directly.
TEST(ReplicationProtocols, Ren2013KeepsThePapersDesign) {
  const ms::Protocol p = load("ren2013_materials");
  const auto& id = std::get<ms::IdentifyBlock>(block(p, "material").body);
  EXPECT_EQ(id.labels, (std::vector<std::string>{"wood", "plastic", "metal", "porcelain", "glass"}));
  EXPECT_EQ(id.stimuli.size(), 22u);
  const auto factor = [](const ms::StimulusSource& s, const std::string& name) {
    for (const auto& [n, level] : s.factors)
      if (n == name) return level;
    return std::string();
  };
  std::map<std::string, std::map<std::string, int>> per_label;  // condition -> truth -> clips
  for (const auto& name : names(id.stimuli)) {
    const ms::StimulusSource* s = p.find_stimulus(name);
    ASSERT_NE(s, nullptr) << name;
    ASSERT_EQ(s->truth.size(), 1u) << name;
    const std::string truth = s->truth.front().second, condition = factor(*s, "condition");
    EXPECT_NE(std::find(id.labels.begin(), id.labels.end(), truth), id.labels.end()) << name;
    EXPECT_EQ(factor(*s, "material"), truth) << name;
    EXPECT_EQ(s->kind == ms::StimulusKind::file, condition == "recorded") << name;
    ++per_label[condition][truth];
  }
  for (const auto& label : id.labels) {
    EXPECT_EQ(per_label["synthesised"][label], label == "glass" ? 4 : 3) << label;  // 3 shapes, or 4 bowl sizes
    EXPECT_NE(p.find_stimulus(label), nullptr) << label;  // the label-named plate (glass: the size-1 bowl)
  }
  // hydrogen-drumkits has metal, wood and glass objects; no plastic or porcelain one.
  EXPECT_EQ(per_label["recorded"], (std::map<std::string, int>{{"glass", 2}, {"metal", 2}, {"wood", 2}}));
  EXPECT_EQ(per_label.size(), 2u);
  EXPECT_EQ(trials_of(ms::make_schedule(p, "P01"), "material").size(), 22u);
}

// Skandalou & Ireland 2017: -3..+3 comparison of sinusoidal vs filter-based synthesis, each pair
// written [sinusoidal, filter-based] (positive = filter-based better), recordings as reference.
TEST(ReplicationProtocols, SynthesisMethodsAbIsBipolar) {
  const ms::Protocol p = load("ab_synthesis_methods");
  const auto& ab = std::get<ms::AbBlock>(block(p, "methods").body);
  EXPECT_EQ(ab.mode, ms::AbMode::bipolar);
  EXPECT_EQ(ab.pairs.size(), 10u);  // 5 objects x 2 areas
  for (const auto& pr : ab.pairs) {
    EXPECT_EQ(pr[0].name.substr(0, 4), "sin-");
    EXPECT_EQ(pr[1].name.substr(0, 4), "bpf-");
    EXPECT_EQ(pr[0].name.substr(4), pr[1].name.substr(4));  // same object and area
    const ms::StimulusSource* rec = p.find_stimulus("rec-" + pr[0].name.substr(4));
    ASSERT_NE(rec, nullptr) << pr[0].name;
    EXPECT_EQ(rec->kind, ms::StimulusKind::file);
  }
  // Each pair carries its object's recording as the reference, played after A and B.
  ASSERT_EQ(ab.references.size(), ab.pairs.size());
  for (std::size_t i = 0; i < ab.pairs.size(); ++i) EXPECT_EQ(ab.references[i].name, "rec-" + ab.pairs[i][0].name.substr(4));
  for (const auto& t : trials_of(ms::make_schedule(p, "P01"), "methods")) {
    ASSERT_EQ(t.stimuli.size(), 3u);
    EXPECT_EQ(t.stimuli[2], t.reference);
    EXPECT_EQ(t.reference.substr(4), t.stimuli[0].substr(4));
  }
}

// The two methods are the thesis's: sin-* is Eq 2.1 as written (cosine onset, unit impulse, the exact
// oscillator bank, d = 2 pi f D), bpf-* the Pd [bp~] bank with the material's Q of Table 4.1; both
// from the same 10 modes of the object, struck at the same area.
TEST(ReplicationProtocols, SynthesisMethodsAreTheThesisMethods) {
  const ms::Protocol p = load("ab_synthesis_methods");
  const std::map<std::string, double> table_4_1_q = {{"plastic", 1000}, {"wood", 1500}, {"ceramic", 3000},
                                                     {"glass", 3500}, {"metal", 4000}};
  const std::string dir = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/";
  // The stimulus as the protocol renders it, or (unpruned) without its `prune:`.
  const auto resolved = [&](const std::string& name, bool unpruned = false) {
    const ms::StimulusSource* s = p.find_stimulus(name);
    if (!s) throw std::runtime_error("no stimulus " + name);
    std::vector<std::string> overrides;
    for (const std::string& o : s->overrides)
      if (!unpruned || o.rfind("prune.", 0) != 0) overrides.push_back(o);
    return ms::load_paramset(dir + s->path, overrides);
  };
  const auto& ab = std::get<ms::AbBlock>(block(p, "methods").body);
  for (const auto& pr : ab.pairs) {
    const ms::ParamSet sin = resolved(pr[0].name), bpf = resolved(pr[1].name);
    const std::string material = pr[0].name.substr(4, pr[0].name.find('-', 4) - 4);
    ASSERT_EQ(table_4_1_q.count(material), 1u) << pr[0].name;
    EXPECT_EQ(sin.renderer, ms::Renderer::resonator) << pr[0].name;
    EXPECT_EQ(bpf.renderer, ms::Renderer::bandpass) << pr[1].name;
    EXPECT_EQ(bpf.bandpass_q, std::vector<double>{table_4_1_q.at(material)}) << pr[1].name;
    EXPECT_EQ(bpf.bandpass_clip, 1.0) << pr[1].name;  // [clip~ -1 1]
    // The 10 strongest modes, or all of them: the bars have fewer below Nyquist (board 6, bottle 9).
    const std::size_t modes = std::min<std::size_t>(10, resolved(pr[0].name, true).model.modes.size());
    for (const ms::ParamSet* set : {&sin, &bpf}) {
      EXPECT_EQ(set->excitation.shape, ms::PulseShape::impulse);
      EXPECT_EQ(set->excitation.gain, 1.0);
      EXPECT_EQ(set->model.modes.size(), modes) << pr[0].name;
    }
    ASSERT_EQ(sin.model.modes.size(), bpf.model.modes.size());
    const double loss_factor = sin.model.modes[0].decay_per_s / (2 * std::numbers::pi * sin.model.modes[0].freq_hz);
    for (std::size_t i = 0; i < sin.model.modes.size(); ++i) {
      const ms::Mode& m = sin.model.modes[i];
      // sin(x + pi/2) = cos x (+ pi where the mode shape is negative at the hit)
      EXPECT_NEAR(std::fmod(m.phase_rad, std::numbers::pi), 0.5 * std::numbers::pi, 1e-12) << pr[0].name;
      EXPECT_NEAR(m.decay_per_s / (2 * std::numbers::pi * m.freq_hz), loss_factor, 1e-12) << pr[0].name;
      // The same modes: the sets' f = f0 sqrt(1 - D^2) differ by at most 0.13% (plastic, D = 0.05).
      EXPECT_NEAR(bpf.model.modes[i].freq_hz / m.freq_hz, 1.0, 1.3e-3) << pr[1].name;
      EXPECT_DOUBLE_EQ(bpf.model.modes[i].amp, m.amp) << pr[1].name;
    }
  }
}

// The simulated listener runs each whole session (as `studyapp --autopilot` would) and answers every
// trial: the protocols are runnable end to end, stimuli, recordings and staircases included.
TEST(ReplicationProtocols, AutopilotAnswersEveryTrial) {
  for (const auto& name : kReplications) {
    const ms::test::TempDir dir;
    ms::AutopilotOptions o;
    o.protocol_path = protocol_path(name);
    o.participant = "P01";
    o.db_path = dir.file(name + ".sqlite");
    o.cache_dir = dir.file("cache");
    o.seed = 1;
    const ms::AutopilotSummary s = ms::run_autopilot(o);
    EXPECT_TRUE(s.finished) << name;
    EXPECT_FALSE(s.resumed) << name;
    EXPECT_GT(s.total, 0u) << name;
    EXPECT_EQ(s.answered_now, s.total) << name;
    EXPECT_EQ(s.total, ms::make_schedule(load(name), "P01").trials.size()) << name;
  }
}

}  // namespace
