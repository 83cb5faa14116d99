#include "analysis/audit/hidden_effect_generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>

#include "synthesis/effects.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/resonator_bank.hpp"
#include "synthesis/room_response.hpp"

namespace ms::audit {

std::vector<std::string> hideable_effects() {
  return {"support_damping",    "damping_law", "mode_doublet", "contact_duration", "noise_floor", "reverberation",
          "residual_transient", "hit_position"};
}

namespace {

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

double strength_of(const std::vector<std::string>& effects, const std::vector<double>& strengths, const std::string& e) {
  for (std::size_t i = 0; i < effects.size(); ++i)
    if (effects[i] == e) return strengths[i];
  return 0.0;
}

// printf into a string, for the case's one-line summary.
[[gnu::format(printf, 1, 2)]] std::string printed(const char* format, ...) {
  char buf[400];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  return buf;
}

using Uniform = std::uniform_real_distribution<double>;

// The object: 10-22 modes, 180 Hz - 7 kHz, at least 4 % apart; Rayleigh damping, or with the
// damping_law effect a hybrid law with exponent 1 -+ (0.15 .. 0.4), equal to the Rayleigh law at 1 kHz.
void draw_object(std::mt19937_64& rng, const std::vector<std::string>& effects, const std::vector<double>& strengths,
                 HiddenCase& hc) {
  Uniform U(0.0, 1.0);
  const int modes = 10 + int(U(rng) * 13);
  std::vector<double> freqs;
  for (int tries = 0; int(freqs.size()) < modes && tries < 10000; ++tries) {
    const double f = 180.0 * std::pow(7000.0 / 180.0, U(rng));
    bool ok = true;
    for (double g : freqs) ok &= std::abs(f - g) > 0.04 * std::min(f, g);
    if (ok) freqs.push_back(f);
  }
  std::sort(freqs.begin(), freqs.end());
  const double a1 = 1.0 + 7.0 * U(rng);                   // c = 2d at 0 Hz, 1/s
  const double c5k = 15.0 + 45.0 * U(rng);                // c at 5 kHz
  const double lambda5k = std::pow(2.0 * std::numbers::pi * 5000.0, 2);
  const double a2 = (c5k - a1) / lambda5k;
  double a3 = 1.0, a2h = a2;
  if (has(effects, "damping_law")) {
    const double u = strength_of(effects, strengths, "damping_law");
    a3 = 1.0 + (U(rng) < 0.5 ? -1.0 : 1.0) * (0.15 + 0.25 * u);
    const double lg = std::pow(2.0 * std::numbers::pi * 1000.0, 2);
    a2h = a2 * lg / std::pow(lg, a3);
  }
  for (double f : freqs) {
    const double lambda = std::pow(2.0 * std::numbers::pi * f, 2);
    const double c = a1 + a2h * std::pow(lambda, a3);
    hc.object.modes.push_back({f, 0.5 * c, std::pow(10.0, -30.0 * U(rng) / 20.0), 0.0});
  }
  hc.summary = printed("seed %llu: %d modes %.0f-%.0f Hz, c = %.2f + %.3g lambda^%.2f", (unsigned long long)hc.seed,
                       modes, freqs.front(), freqs.back(), a1, a2h, a3);
}

// Strike gains: stratified over 20 dB (every audit sees soft and hard strikes), in random order.
std::vector<double> draw_strike_gains(std::mt19937_64& rng, std::size_t strikes) {
  Uniform U(0.0, 1.0);
  std::vector<double> gains;
  for (std::size_t s = 0; s < strikes; ++s)
    gains.push_back(std::pow(10.0, -20.0 * ((double(s) + U(rng)) / double(strikes)) / 20.0));
  std::shuffle(gains.begin(), gains.end(), rng);
  return gains;
}

// The hidden effects' physical parameters, drawn once per case (none where an effect is not hidden).
struct EffectParameters {
  std::vector<std::size_t> doublets;  // modes split in two
  double split_hz = 0.0, balance = 0.5;
  double support_mean_per_s = 0.0;    // mean excess decay of the support
  double tau_hard_s = 0.0;            // contact of the hardest strike
  double contact_exponent = 0.0;      // tau = tau_hard (g / g_max)^-p
  double noise_below_db = 110.0;      // under the hardest strike's strongest mode
  Room room;
  AttackTransient transient;
  // hit_position: mode n's shape sin(k_n x + theta_n) (k_n x in radians, x a fraction of the object's
  // length), struck at x_s per strike; amplitudes relative to the shape at the nominal hit x = 0.5.
  std::vector<double> hit_wavenumber, hit_phase, strike_hit;
};

// Mode n's amplitude at hit x relative to the nominal hit; a node keeps a tenth of an antinode's
// amplitude (the strike is not a point), so no mode disappears.
double hit_shape_factor(const EffectParameters& e, std::size_t n, double x) {
  const auto shape = [&](double at) { return 0.1 + std::abs(std::sin(e.hit_wavenumber[n] * at + e.hit_phase[n])); };
  return shape(x) / shape(0.5);
}

// mode_doublet: 1-2 of the slower-decaying modes below 3 kHz split by 1.5-4.5 Hz.
void draw_doublets(std::mt19937_64& rng, double u, const ModalModel& object, EffectParameters& e, std::string& summary) {
  e.split_hz = 1.5 + 3.0 * u;
  e.balance = 0.35 + 0.3 * Uniform(0.0, 1.0)(rng);
  std::vector<std::size_t> order;
  for (std::size_t n = 0; n < object.modes.size(); ++n)
    if (object.modes[n].freq_hz < 3000.0) order.push_back(n);
  std::sort(order.begin(), order.end(),
            [&](std::size_t x, std::size_t y) { return object.modes[x].amp > object.modes[y].amp; });
  for (std::size_t i = 0; i < order.size() && i < 2; ++i) e.doublets.push_back(order[i]);
  summary += printed("; doublets: %zu split %.2f Hz", e.doublets.size(), e.split_hz);
}

// Every hidden effect's parameters, in the order of their draws: the first five from the object's
// generator, the later ones from their own, so cases hiding only the first five stay as they were.
EffectParameters draw_effects(std::mt19937_64& rng, const std::vector<std::string>& effects,
                              const std::vector<double>& strengths, HiddenCase& hc) {
  EffectParameters e;
  auto hidden = [&](const char* name) { return has(effects, name); };
  auto strength = [&](const char* name) { return strength_of(effects, strengths, name); };
  if (hidden("mode_doublet")) draw_doublets(rng, strength("mode_doublet"), hc.object, e, hc.summary);
  // support_damping: per strike a hold factor in [0.3, 1] times Exp draws of mean (0.5-2) x median decay.
  if (hidden("support_damping")) {
    std::vector<double> d;
    for (const Mode& m : hc.object.modes) d.push_back(m.decay_per_s);
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
    e.support_mean_per_s = (0.5 + 1.5 * strength("support_damping")) * d[d.size() / 2];
    hc.summary += printed("; support excess mean %.2f 1/s", e.support_mean_per_s);
  }
  // contact_duration: raised cosine, tau = tau_hard (g / g_max)^-p.
  if (hidden("contact_duration")) {
    const double u = strength("contact_duration");
    e.tau_hard_s = (0.1 + 0.3 * u) * 1e-3;
    e.contact_exponent = 0.4 + 0.3 * u;
    hc.summary += printed("; contact %.2f ms (hardest) x gain^-%.2f", e.tau_hard_s * 1e3, e.contact_exponent);
  }
  // Noise: a faint floor always (110 dB below the strongest mode of the hardest strike), or the
  // noise_floor effect's 40-60 dB below it (fainter noise sits under the gap metric's 60 dB floor).
  if (hidden("noise_floor")) {
    e.noise_below_db = 60.0 - 20.0 * strength("noise_floor");
    hc.summary += printed("; noise %.1f dB below the strongest mode", e.noise_below_db);
  }
  std::mt19937_64 rng2(hc.seed * 1000003u + 11u);
  Uniform U(0.0, 1.0);
  // reverberation: a room (synthesis/room_response), the same impulse response for every strike. RT60
  // 0.4-1 s at 125 Hz falling log-linearly over the octaves to 0.3 s .. that at 8 kHz (air and walls
  // absorb the highs), DRR +8 .. -2 dB. Drawn from a stream of its own: the transient's draws stay.
  if (hidden("reverberation")) {
    std::mt19937_64 rng_room(hc.seed * 2862933555777941757ULL + 3037000493ULL);
    const double t_low = 0.4 + 0.6 * U(rng_room), t_high = 0.3 + (t_low - 0.3) * U(rng_room);
    const std::size_t bands = kRoomOctaveCentresHz.size();
    std::vector<double> rt60_s;
    for (std::size_t b = 0; b < bands; ++b) rt60_s.push_back(t_low * std::pow(t_high / t_low, double(b) / double(bands - 1)));
    e.room = {.rt60_s = rt60_s, .drr_db = 8.0 - 10.0 * strength("reverberation"), .seed = hc.seed * 131u + 7u,
              .enabled = true};
    hc.summary += printed("; room RT60 %.2f s (125 Hz) .. %.2f s (8 kHz), DRR %.1f dB", t_low, t_high, e.room.drr_db);
  }
  // residual_transient: a white burst decaying 60 dB in 3-10 ms, -30 .. -15 dB re the direct sound.
  if (hidden("residual_transient")) {
    e.transient = {-30.0 + 15.0 * strength("residual_transient"), 3.0 + 7.0 * U(rng2), 0, true};
    hc.summary += printed("; transient %.1f ms at %.1f dB", e.transient.duration_ms, e.transient.level_db);
  }
  // hit_position: flexural shapes, k_n = 4.73 sqrt(f_n / f_1) (a free bar's first root, k ~ sqrt(f));
  // strikes within 0.5 -+ (0.02 .. 0.1) of the length (a hand moving a few millimetres to centimetres).
  // A stream of its own.
  if (hidden("hit_position")) {
    std::mt19937_64 rng3(hc.seed * 6364136223846793005ULL + 1442695040888963407ULL);
    const double f1 = hc.object.modes.front().freq_hz, half_width = 0.02 + 0.08 * strength("hit_position");
    for (const Mode& m : hc.object.modes) {
      e.hit_wavenumber.push_back(4.73 * std::sqrt(m.freq_hz / f1));
      e.hit_phase.push_back(2.0 * std::numbers::pi * U(rng3));
    }
    for (std::size_t s = 0; s < hc.strike_gain.size(); ++s) e.strike_hit.push_back(0.5 + half_width * (2.0 * U(rng3) - 1.0));
    hc.summary += printed("; hit points 0.5 -+ %.2f of the length", half_width);
  }
  return e;
}

// The draws every strike makes, in turn, from the object's generator (the normal distribution keeps
// its state from one strike to the next).
struct StrikeDraws {
  std::mt19937_64& rng;
  std::normal_distribution<double> normal{0.0, 1.0};
  std::exponential_distribution<double> exponential{1.0};
};

// The object's modes for strike s: scaled to its gain, with the support's excess decay and the split modes.
ModalModel strike_modes(const HiddenCase& hc, std::size_t s, double scale, const EffectParameters& e,
                        const GeneratorOptions& opt, StrikeDraws& draws) {
  ModalModel m;
  const double hold = 0.3 + 0.7 * Uniform(0.0, 1.0)(draws.rng);
  std::mt19937_64 jitter_rng(hc.seed * 2654435761u + 977u * (s + 1));
  std::normal_distribution<double> jitter(0.0, 1.0);
  for (std::size_t n = 0; n < hc.object.modes.size(); ++n) {
    Mode mode = hc.object.modes[n];
    mode.amp *= scale * hc.strike_gain[s];
    if (!e.strike_hit.empty()) mode.amp *= hit_shape_factor(e, n, e.strike_hit[s]);
    if (opt.amplitude_jitter_db > 0.0) mode.amp *= std::pow(10.0, opt.amplitude_jitter_db * jitter(jitter_rng) / 20.0);
    if (e.support_mean_per_s > 0.0) mode.decay_per_s += hold * e.support_mean_per_s * draws.exponential(draws.rng);
    if (std::find(e.doublets.begin(), e.doublets.end(), n) != e.doublets.end()) {
      Mode hi = mode;
      mode.freq_hz -= 0.5 * e.split_hz;
      hi.freq_hz += 0.5 * e.split_hz;
      const double norm = std::hypot(1.0 - e.balance, e.balance);
      mode.amp *= (1.0 - e.balance) / norm;
      hi.amp *= e.balance / norm;
      m.modes.push_back(hi);
    }
    m.modes.push_back(mode);
  }
  return m;
}

// Strike s rendered with its contact, room and transient, after a pre-roll, with the noise floor.
Recording render_strike(const HiddenCase& hc, std::size_t s, double scale, double gmax, const EffectParameters& e,
                        const GeneratorOptions& opt, StrikeDraws& draws) {
  const double fs = opt.sample_rate_hz;
  const std::size_t pre = std::size_t(opt.pre_roll_s * fs), frames = std::size_t(opt.duration_s * fs);
  ModalModel m = strike_modes(hc, s, scale, e, opt, draws);
  Excitation excitation;
  if (e.tau_hard_s > 0.0) {
    excitation.shape = PulseShape::raised_cosine;
    excitation.contact_s = e.tau_hard_s * std::pow(hc.strike_gain[s] / gmax, -e.contact_exponent);
  }
  drop_modes_at_or_above(m, 0.5 * fs);
  std::vector<float> y = render_bank(m, excitation, fs, frames);
  apply_room(y, fs, e.room);
  AttackTransient transient = e.transient;
  transient.seed = (hc.seed * 131u + s) ^ 0x5851f42d4c957f2dULL;
  add_reverb_and_transient(y, fs, Reverb{}, transient);
  Recording r;
  r.name = "strike" + std::to_string(s + 1);
  r.sample_rate_hz = fs;
  r.samples.assign(pre + frames, 0.0f);
  for (std::size_t i = 0; i < frames; ++i) r.samples[pre + i] = y[i];
  const double sigma = 0.3 * std::pow(10.0, -e.noise_below_db / 20.0);
  for (float& v : r.samples) v = float(double(v) + sigma * draws.normal(draws.rng));
  return r;
}

}  // namespace

HiddenCase generate_hidden_case(std::uint64_t seed, const std::vector<std::string>& effects,
                                const std::vector<double>& strengths, const GeneratorOptions& opt) {
  if (effects.size() != strengths.size()) throw std::invalid_argument("one strength per hidden effect");
  for (std::size_t i = 0; i < effects.size(); ++i) {
    if (!has(hideable_effects(), effects[i])) throw std::invalid_argument("unknown effect '" + effects[i] + "'");
    if (!(strengths[i] >= 0.0 && strengths[i] <= 1.0)) throw std::invalid_argument("strength must lie in [0, 1]");
  }
  HiddenCase hc;
  hc.seed = seed;
  hc.effects = effects;
  hc.strengths = strengths;
  std::mt19937_64 rng(seed);
  draw_object(rng, effects, strengths, hc);
  hc.strike_gain = draw_strike_gains(rng, opt.strikes);
  const double gmax = *std::max_element(hc.strike_gain.begin(), hc.strike_gain.end());
  const EffectParameters e = draw_effects(rng, effects, strengths, hc);
  if (opt.amplitude_jitter_db > 0.0) hc.summary += printed("; mode amplitudes jittered %.1f dB per strike", opt.amplitude_jitter_db);
  double amax = 0.0;
  for (const Mode& m : hc.object.modes) amax = std::max(amax, m.amp);
  const double scale = 0.3 / (amax * gmax);  // the hardest strike's strongest mode at 0.3 full scale
  StrikeDraws draws{rng};
  for (std::size_t s = 0; s < opt.strikes; ++s) hc.recordings.push_back(render_strike(hc, s, scale, gmax, e, opt, draws));
  return hc;
}

}  // namespace ms::audit
