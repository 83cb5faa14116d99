// The audit's room model (room_power.hpp: a room's expected power in closed form) held to the
// independent generator's truth: each strike rendered from the modes the generator drew for it (its
// jitter included) with and without the generator's room, one overall level and each mode's amplitude
// read from the recordings (in a room a mode's amplitude carries the room's response at its frequency,
// one draw of the room's noise, the same in every strike). Knowing each strike's amplitude jitter is
// more than any model of the strikes can know, so the fair reference leaves it out: the object's modes
// at each strike's gain. Beside it: the true modes in the room the audit fitted, and the audit's own
// modes in the true room, which split the audit's shortfall between its room fit and its mode tracks.
// And a hidden law held to the same truth: how much it lowers the gap below the nearest Rayleigh law's
// with every mode and the room true, which tells the laws no gap can show from those the audit misses.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/audit/audit.hpp"
#include "analysis/audit/audit_model.hpp"
#include "analysis/audit/baseline_fit.hpp"
#include "analysis/audit/room_fit.hpp"
#include "analysis/audit/room_power.hpp"
#include "../audit_cases.hpp"
#include "independent_generator.hpp"

namespace ms::test {
namespace {

// Octave centres 125 Hz-8 kHz in the generator's room bands (below 500, 500-2000, 2000-6000 Hz, above).
constexpr std::array<std::size_t, 7> kGeneratorBandOfOctave{0, 0, 1, 1, 2, 2, 3};

struct TruthFit {
  double level_only_db = 0.0;      // the true modes at one fitted overall level
  double amplitudes_read_db = 0.0; // ... and each mode's amplitude read from the recordings
  double log_level = 0.0;          // the overall level found
};

ms::Room true_room(const indep::IndependentCase& c) {
  ms::Room room;
  room.enabled = true;
  for (std::size_t b : kGeneratorBandOfOctave) room.rt60_s.push_back(c.room.rt60_s[b]);
  room.drr_db = c.room.drr_db;
  return room;
}

// Mean gap of the strikes against their true modes, in `room` if given; with `jitter`, each strike's
// modes as rendered, else without their per-strike amplitude jitter.
// noise: a noise floor per Bark band (audit::AuditModel::noise_band_variance) added to each strike's modes.
// decay_shift (if given): added to mode n's decay in every strike (a law's change, each strike's own
// excess kept). at_log_level (if given): the overall level, not searched; level_only_db alone is filled.
TruthFit truth_gap(const indep::IndependentCase& c, const audit::AuditData& data, const ms::Room* room, bool jitter,
                   const std::vector<double>& noise = {}, const std::vector<double>* decay_shift = nullptr,
                   const double* at_log_level = nullptr) {
  const std::size_t strikes = data.strike_count(), modes = c.strikes[0].modes.size();
  const double fs = data.measured.sample_rate_hz;
  std::vector<double> factor(modes, 1.0);
  const auto gap_at = [&](double log_level) {
    double total = 0.0;
    for (std::size_t s = 0; s < strikes; ++s) {
      audit::AuditModel m;
      m.gain.assign(strikes, 1.0);
      m.noise_band_variance = noise;
      for (std::size_t n = 0; n < modes; ++n) {
        const indep::DampedMode& t = c.strikes[s].modes[n];
        const double decay_per_s = decay_shift ? std::max(1e-3, t.decay_per_s + (*decay_shift)[n]) : t.decay_per_s;
        m.modes.push_back({.freq_hz = t.freq_hz, .decay_per_s = decay_per_s,
                           .amp = std::abs(t.amp) * std::exp(log_level) * factor[n] *
                                  (jitter ? 1.0 : std::pow(10.0, -c.strikes[s].jitter_db[n] / 20.0)),
                           .track = 0,
                           .phase_rad = t.amp < 0.0 ? std::numbers::pi : 0.0});
      }
      if (room) {
        m.room = *room;
        // The true modes are dry; the model takes measured amplitudes to dry ones: undo that.
        const audit::RoomRates rates = audit::room_rates(m.room, fs);
        for (audit::AuditMode& am : m.modes)
          am.room_gain = 1.0 / std::sqrt(audit::dry_power_scale(rates, room_octave_band(am.freq_hz), am.decay_per_s / fs));
      }
      total += audit::strike_gap(m, data, s).gap_db;
    }
    return total / double(strikes);
  };
  if (at_log_level) return {.level_only_db = gap_at(*at_log_level), .log_level = *at_log_level};
  double best = 1e300, level = 0.0;
  for (double l = -12.0; l <= 12.0; l += 0.5)
    if (const double g = gap_at(l); g < best) { best = g; level = l; }
  for (double l = level - 0.5; l <= level + 0.5; l += 0.05)
    if (const double g = gap_at(l); g < best) { best = g; level = l; }
  TruthFit fit{.level_only_db = best, .log_level = level};
  for (std::size_t n = 0; n < modes; ++n) {  // one sweep, mode by mode
    double kept = factor[n];
    for (double lx = -1.5; lx <= 1.51; lx += 0.5) {
      factor[n] = kept * std::exp(lx);
      if (const double g = gap_at(level); g < best) { best = g; kept = factor[n]; }
    }
    factor[n] = kept;
  }
  fit.amplitudes_read_db = best;
  return fit;
}

// The shift of each object mode's decay from its law to the Rayleigh law closest to it (relative least
// squares), that law scaled at the lowest and the highest mode by the factors of a 7 x 7 grid, the one
// whose gap is lowest at the overall level the true decays take: the best a Rayleigh law does with
// everything else true.
std::vector<double> shift_to_nearest_rayleigh(const indep::IndependentCase& c, const audit::AuditData& data,
                                              const ms::Room* room) {
  if (c.object.size() != c.strikes[0].modes.size()) throw std::invalid_argument("a doublet splits a mode");
  std::vector<DampingPoint> points;
  double f_lo = 1e300, f_hi = 0.0;
  for (const indep::ObjectMode& m : c.object) {
    points.push_back(damping_point(m.freq_hz, m.decay_per_s));
    f_lo = std::min(f_lo, m.freq_hz);
    f_hi = std::max(f_hi, m.freq_hz);
  }
  const DampingLaw fitted = audit::fit_law_relative(points, DampingKind::rayleigh);
  const auto d_at = [&](double f) {
    const double w = 2.0 * std::numbers::pi * f;
    return fitted.decay_per_s(w * w);
  };
  const auto shift_of = [&](double scale_lo, double scale_hi) {
    // d = a + b f^2 through the scaled law's values at f_lo and f_hi.
    const double d_lo = scale_lo * d_at(f_lo), d_hi = scale_hi * d_at(f_hi);
    const double b = std::max(0.0, (d_hi - d_lo) / (f_hi * f_hi - f_lo * f_lo)), a = std::max(0.0, d_lo - b * f_lo * f_lo);
    std::vector<double> shift;
    for (const indep::ObjectMode& m : c.object) shift.push_back(a + b * m.freq_hz * m.freq_hz - m.decay_per_s);
    return shift;
  };
  const double level = truth_gap(c, data, room, false).log_level;
  std::vector<double> best;
  double best_gap = 1e300;
  for (double lo : {0.8, 0.87, 0.93, 1.0, 1.07, 1.15, 1.25})
    for (double hi : {0.7, 0.8, 0.9, 1.0, 1.12, 1.25, 1.4}) {
      const std::vector<double> shift = shift_of(lo, hi);
      if (const double g = truth_gap(c, data, room, false, {}, &shift, &level).level_only_db; g < best_gap) {
        best_gap = g;
        best = shift;
      }
    }
  return best;
}

// The true modes (without their jitter, each amplitude read) with their own decays and on the nearest
// Rayleigh law, in `room` if given.
struct LawGain {
  TruthFit with_law, on_rayleigh;
  double gain_db() const { return on_rayleigh.amplitudes_read_db - with_law.amplitudes_read_db; }
};

LawGain law_gain(const indep::IndependentCase& c, const audit::AuditData& data, const ms::Room* room) {
  const std::vector<double> shift = shift_to_nearest_rayleigh(c, data, room);
  return {truth_gap(c, data, room, false), truth_gap(c, data, room, false, {}, &shift)};
}

// The case ORACLE_SEED, ORACLE_EFFECTS and ORACLE_STRENGTHS name.
indep::IndependentCase oracle_case() {
  std::vector<std::string> effects;
  std::vector<double> strengths;
  env_case("ORACLE", effects, strengths);
  const char* seed = std::getenv("ORACLE_SEED");
  if (seed == nullptr) throw std::invalid_argument("set ORACLE_SEED");
  return indep::generate_independent_case(std::stoull(seed), effects, strengths);
}

// The audit's modes (its final model's, dry) in `room`, each amplitude read again as the room's fit does.
// answers: then also each mode's amplitude and the room's answer to it read in that room.
double audit_modes_in(const audit::AuditData& data, const audit::AuditModel& audited, const ms::Room& room,
                      bool answers = false) {
  audit::AuditModel m = audited;
  m.room = {};
  for (audit::AuditMode& mode : m.modes) {
    mode.room_gain = 1.0;
    mode.room_answer = 1.0;
  }
  audit::read_mode_amplitudes(data, m, room, audit::all_strikes(data), std::vector<bool>(m.modes.size(), false)).apply(m);
  m.room = room;
  if (answers) audit::read_amplitudes_in_room(data, m, audit::all_strikes(data));
  return audit::mean_gap(m, data);
}

// Tuning seed 40504 (39 modes 213-5142 Hz, 6 strikes, jitter 2 dB): clean, the true modes are the
// recordings, and without their jitter they leave what the audit leaves (~1.3 dB); in its strongest
// room (RT60 0.85/0.78/0.64/0.54 s, DRR -1 dB) the room's expected power explains part of what the
// room does, not all: a room's answer at each frequency is one draw. Measured: the fair truth reaches
// 2.69 dB where the audit reaches 3.72; the true modes in the audit's room (DRR 10.3 dB) 3.26; the
// audit's modes in the true room 3.69: the tracks fall short most, and the room fit too.
TEST(AuditRoomOracle, TheRoomModelWithTheTrueModesExplainsPartOfAStrongRoom) {
  const indep::IndependentCase clean = indep::generate_independent_case(40504, {}, {});
  const audit::AuditData clean_data = audit::make_audit_data(clean.recordings);
  const TruthFit c = truth_gap(clean, clean_data, nullptr, true), cu = truth_gap(clean, clean_data, nullptr, false);
  std::printf("%s\n  true modes: gap %.2f dB; without their jitter %.2f dB\n", clean.summary.c_str(), c.level_only_db,
              cu.amplitudes_read_db);
  EXPECT_LT(c.level_only_db, 0.1);

  const indep::IndependentCase roomed = indep::generate_independent_case(40504, {"reverberation"}, {0.9});
  const audit::AuditData data = audit::make_audit_data(roomed.recordings);
  const ms::Room truth = true_room(roomed);
  const TruthFit dry = truth_gap(roomed, data, nullptr, true), wet = truth_gap(roomed, data, &truth, true);
  const TruthFit fair_dry = truth_gap(roomed, data, nullptr, false), fair_wet = truth_gap(roomed, data, &truth, false);
  const audit::AuditResult r = audit::run_audit(data);
  ASSERT_TRUE(r.final_model.room.enabled) << "the audit fitted no room";
  const TruthFit in_fitted = truth_gap(roomed, data, &r.final_model.room, false);
  std::printf("%s\n  true modes without the room: gap %.2f dB, amplitudes read %.2f dB (without their jitter %.2f dB)\n"
              "  true modes in the true room: gap %.2f dB, amplitudes read %.2f dB (without their jitter %.2f dB)\n"
              "  the audit: baseline %.2f dB, floor %.2f dB, after %.2f dB (room DRR %.1f dB), named:",
              roomed.summary.c_str(), dry.level_only_db, dry.amplitudes_read_db, fair_dry.amplitudes_read_db,
              wet.level_only_db, wet.amplitudes_read_db, fair_wet.amplitudes_read_db, r.gap_before_db, r.floor_db,
              r.gap_after_db, r.final_model.room.drr_db);
  for (const auto& n : r.named) std::printf(" %s", n.effect.c_str());
  std::printf("\n  true modes (without their jitter) in the audit's room: %.2f dB; the audit's modes in the true room: "
              "%.2f dB\n", in_fitted.amplitudes_read_db, audit_modes_in(data, r.final_model, truth));
  EXPECT_LT(wet.level_only_db, dry.level_only_db - 0.5);
  EXPECT_LT(wet.amplitudes_read_db, dry.amplitudes_read_db - 0.5);
  EXPECT_LT(fair_wet.amplitudes_read_db, fair_dry.amplitudes_read_db - 0.5);
  // Not all: even the truth stays well above the clean strikes' gap.
  EXPECT_GT(fair_wet.amplitudes_read_db, cu.amplitudes_read_db + 0.5);
}

// Some rooms the generator hides no gap can show: behind modes that outlast it, a short room acts as a
// gain on each mode, which the mode's own amplitude takes up. Held-out seed 46207 (RT60 0.58-0.27 s,
// DRR 4.3 dB, mode decays of 1.7 s and more), missed by the audit: its true modes, each amplitude read
// from the recordings, gain 0.14 dB from the true room, a seventh of the audit's 1 dB bar for a room.
// 46251 (RT60 1.11-0.50 s, DRR 5.5 dB), also missed, is not of that kind: there the true room gains
// 0.80 dB, and the audit's room 0.84 dB.
TEST(AuditRoomOracle, AShortRoomBehindSlowModesBarelyMovesEvenTheTrueModesGap) {
  const struct {
    std::uint64_t seed;
    double strength;
  } cases[] = {{46207, 0.3713333625811765}, {46251, 0.24962029548060219}};
  double gain_db[2];
  for (std::size_t i = 0; i < 2; ++i) {
    const indep::IndependentCase c = indep::generate_independent_case(cases[i].seed, {"reverberation"}, {cases[i].strength});
    const audit::AuditData data = audit::make_audit_data(c.recordings);
    const ms::Room truth = true_room(c);
    const double dry = truth_gap(c, data, nullptr, false).amplitudes_read_db;
    const double wet = truth_gap(c, data, &truth, false).amplitudes_read_db;
    gain_db[i] = dry - wet;
    std::printf("%s\n  true modes without their jitter: %.2f dB dry, %.2f dB in the true room\n", c.summary.c_str(), dry, wet);
  }
  EXPECT_LT(gain_db[0], 0.3);
  EXPECT_GT(gain_db[1], 0.5);
}

// The truth's view of a law, for sorting the audit's misses: with every mode's frequency, amplitude and
// the room true, how much the generator's law lowers the gap below the nearest Rayleigh law's
// (shift_to_nearest_rayleigh). Two laws beside a room the audit missed on a held-out run: on 49521
// (strength 0.02, DRR 2.1 dB) the Rayleigh law does 0.10 dB better, so no audit could name it; on 49620
// (strength 0.82, DRR 5.6 dB) the law gains 0.66 dB, more than laws the audit names alone (0.11-0.33 dB
// on 49514, 49547, 49558): that miss is the audit's, whose decays in a room are read off each mode and
// the room's answer to it together.
TEST(AuditRoomOracle, AWeakLawBesideARoomIsInvisibleEvenToTheTruthAStrongOneIsNot) {
  const struct {
    std::uint64_t seed;
    double law, room;
  } cases[] = {{49521, 0.024625923440716051, 0.58894586418053396}, {49620, 0.81892822680349731, 0.23820019670587922}};
  // Generated one after the other, then held to the truth side by side (each takes tens of seconds).
  std::vector<indep::IndependentCase> generated;
  std::vector<audit::AuditData> data;
  for (const auto& k : cases) {
    generated.push_back(indep::generate_independent_case(k.seed, {"damping_law", "reverberation"}, {k.law, k.room}));
    data.push_back(audit::make_audit_data(generated.back().recordings));
  }
  std::future<LawGain> done[2];
  for (std::size_t i = 0; i < 2; ++i)
    done[i] = std::async(std::launch::async, [&, i] {
      const ms::Room truth = true_room(generated[i]);
      return law_gain(generated[i], data[i], &truth);
    });
  double gain_db[2];
  for (std::size_t i = 0; i < 2; ++i) {
    const LawGain g = done[i].get();
    gain_db[i] = g.gain_db();
    std::printf("%s\n  true modes in the true room: %.3f dB, on the nearest Rayleigh law %.3f dB\n",
                generated[i].summary.c_str(), g.with_law.amplitudes_read_db, g.on_rayleigh.amplitudes_read_db);
  }
  EXPECT_LT(gain_db[0], 0.05);  // damping_law's penalty
  EXPECT_GT(gain_db[1], 0.5);
}

// One case of the independent generator held to its truth (disabled; --gtest_also_run_disabled_tests):
// ORACLE_SEED=S ORACLE_EFFECTS=a,b ORACLE_STRENGTHS=u,v (all digits, as the held-out runs print them).
// A noise floor the audit named is added to the true modes too.
TEST(AuditRoomOracle, DISABLED_Case) {
  const indep::IndependentCase c = oracle_case();
  ASSERT_TRUE(c.has_room) << "the case hides no room";
  const audit::AuditData data = audit::make_audit_data(c.recordings);
  const audit::AuditResult r = audit::run_audit(data);
  const std::vector<double>& noise = r.final_model.noise_band_variance;
  const ms::Room truth = true_room(c);
  const TruthFit fair_dry = truth_gap(c, data, nullptr, false, noise), fair_wet = truth_gap(c, data, &truth, false, noise);
  std::printf("%s\n  the audit: baseline %.2f dB, floor %.2f dB, after %.2f dB (room %s, DRR %.1f dB), named:",
              c.summary.c_str(), r.gap_before_db, r.floor_db, r.gap_after_db, r.final_model.room.enabled ? "on" : "off",
              r.final_model.room.drr_db);
  for (const auto& n : r.named) std::printf(" %s", n.effect.c_str());
  std::printf("\n  true modes without their jitter%s: dry %.2f dB, in the true room %.2f dB\n",
              noise.empty() ? "" : " (with the audit's noise floor)", fair_dry.amplitudes_read_db,
              fair_wet.amplitudes_read_db);
  if (r.final_model.room.enabled)
    std::printf("  true modes in the audit's room: %.2f dB\n",
                truth_gap(c, data, &r.final_model.room, false, noise).amplitudes_read_db);
  std::printf("  the audit's modes (%zu) in the true room: %.2f dB; with the room's answers read: %.2f dB\n",
              r.final_model.modes.size(), audit_modes_in(data, r.final_model, truth),
              audit_modes_in(data, r.final_model, truth, true));
  EXPECT_GT(fair_dry.amplitudes_read_db, 0.0);
}

// How much a hidden damping law shows in the gap when everything else is true (disabled;
// --gtest_also_run_disabled_tests): ORACLE_SEED=S ORACLE_EFFECTS=a,b ORACLE_STRENGTHS=u,v. The true
// modes without their jitter, each amplitude read, with their true decays and with the nearest
// Rayleigh law's (each strike's hand damping kept), in the true room where the case hides one.
TEST(AuditRoomOracle, DISABLED_LawCase) {
  const indep::IndependentCase c = oracle_case();
  const audit::AuditData data = audit::make_audit_data(c.recordings);
  const ms::Room truth = c.has_room ? true_room(c) : ms::Room{};
  const LawGain g = law_gain(c, data, c.has_room ? &truth : nullptr);
  std::printf("%s\n  true modes without their jitter%s: true decays %.3f dB, nearest Rayleigh law %.3f dB: the law "
              "gains %.3f dB (level only %.3f dB)\n", c.summary.c_str(), c.has_room ? ", in the true room" : "",
              g.with_law.amplitudes_read_db, g.on_rayleigh.amplitudes_read_db, g.gain_db(),
              g.on_rayleigh.level_only_db - g.with_law.level_only_db);
  EXPECT_GT(g.with_law.amplitudes_read_db, 0.0);
}

}  // namespace
}  // namespace ms::test
