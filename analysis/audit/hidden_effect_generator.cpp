#include "analysis/audit/hidden_effect_generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>

#include "synthesis/effects.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/resonator_bank.hpp"

namespace ms::audit {

std::vector<std::string> hideable_effects() {
  return {"support_damping",    "damping_law", "mode_doublet", "contact_duration", "noise_floor", "reverberation",
          "residual_transient"};
}

namespace {

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

double strength_of(const std::vector<std::string>& effects, const std::vector<double>& strengths, const std::string& e) {
  for (std::size_t i = 0; i < effects.size(); ++i)
    if (effects[i] == e) return strengths[i];
  return 0.0;
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
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double fs = opt.sample_rate_hz;

  // The object: 10-22 modes, 180 Hz - 7 kHz, at least 4 % apart; Rayleigh damping.
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
  // damping_law: a hybrid law with exponent 1 -+ (0.15 .. 0.4), equal to the Rayleigh law at 1 kHz.
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
  char buf[400];
  std::snprintf(buf, sizeof buf, "seed %llu: %d modes %.0f-%.0f Hz, c = %.2f + %.3g lambda^%.2f",
                (unsigned long long)seed, modes, freqs.front(), freqs.back(), a1, a2h, a3);
  hc.summary = buf;

  // Strike gains: stratified over 20 dB (every audit sees soft and hard strikes).
  const std::size_t S = opt.strikes;
  for (std::size_t s = 0; s < S; ++s)
    hc.strike_gain.push_back(std::pow(10.0, -20.0 * ((double(s) + U(rng)) / double(S)) / 20.0));
  std::shuffle(hc.strike_gain.begin(), hc.strike_gain.end(), rng);
  const double gmax = *std::max_element(hc.strike_gain.begin(), hc.strike_gain.end());

  // mode_doublet: 1-2 of the slower-decaying modes below 3 kHz split by 1.5-4.5 Hz.
  std::vector<std::size_t> doublets;
  double split_hz = 0.0, balance = 0.5;
  if (has(effects, "mode_doublet")) {
    const double u = strength_of(effects, strengths, "mode_doublet");
    split_hz = 1.5 + 3.0 * u;
    balance = 0.35 + 0.3 * U(rng);
    std::vector<std::size_t> order;
    for (std::size_t n = 0; n < hc.object.modes.size(); ++n)
      if (hc.object.modes[n].freq_hz < 3000.0) order.push_back(n);
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return hc.object.modes[x].amp > hc.object.modes[y].amp;
    });
    for (std::size_t i = 0; i < order.size() && i < 2; ++i) doublets.push_back(order[i]);
    std::snprintf(buf, sizeof buf, "; doublets: %zu split %.2f Hz", doublets.size(), split_hz);
    hc.summary += buf;
  }
  // support_damping: per strike a hold factor in [0.3, 1] times Exp draws of mean (0.5-2) x median decay.
  double support_mean = 0.0;
  if (has(effects, "support_damping")) {
    std::vector<double> d;
    for (const Mode& m : hc.object.modes) d.push_back(m.decay_per_s);
    std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
    support_mean = (0.5 + 1.5 * strength_of(effects, strengths, "support_damping")) * d[d.size() / 2];
    std::snprintf(buf, sizeof buf, "; support excess mean %.2f 1/s", support_mean);
    hc.summary += buf;
  }
  // contact_duration: raised cosine, tau = tau_hard (g / g_max)^-p.
  double tau_hard = 0.0, p = 0.0;
  if (has(effects, "contact_duration")) {
    const double u = strength_of(effects, strengths, "contact_duration");
    tau_hard = (0.1 + 0.3 * u) * 1e-3;
    p = 0.4 + 0.3 * u;
    std::snprintf(buf, sizeof buf, "; contact %.2f ms (hardest) x gain^-%.2f", tau_hard * 1e3, p);
    hc.summary += buf;
  }
  // Noise: a faint floor always (110 dB below the strongest mode of the hardest strike), or the
  // noise_floor effect's 40-60 dB below it (fainter noise sits under the gap metric's 60 dB floor).
  double amax = 0.0;
  for (const Mode& m : hc.object.modes) amax = std::max(amax, m.amp);
  const double scale = 0.3 / (amax * gmax);  // the hardest strike's strongest mode at 0.3 full scale
  double noise_below_db = 110.0;
  if (has(effects, "noise_floor")) {
    noise_below_db = 60.0 - 20.0 * strength_of(effects, strengths, "noise_floor");
    std::snprintf(buf, sizeof buf, "; noise %.1f dB below the strongest mode", noise_below_db);
    hc.summary += buf;
  }
  const double sigma = 0.3 * std::pow(10.0, -noise_below_db / 20.0);
  // The later effects draw from their own generator: cases hiding only the first five stay as they were.
  std::mt19937_64 rng2(seed * 1000003u + 11u);
  // reverberation: a white tail of RT60 0.2-0.8 s, -48 .. -34 dB re the direct sound (louder tails
  // bury the faint modes the extraction needs).
  Reverb reverb;
  if (has(effects, "reverberation")) {
    reverb = {0.2 + 0.6 * U(rng2), -48.0 + 14.0 * strength_of(effects, strengths, "reverberation"), 0, true};
    std::snprintf(buf, sizeof buf, "; reverb RT60 %.2f s at %.1f dB", reverb.rt60_s, reverb.level_db);
    hc.summary += buf;
  }
  // residual_transient: a white burst decaying 60 dB in 3-10 ms, -30 .. -15 dB re the direct sound.
  AttackTransient transient;
  if (has(effects, "residual_transient")) {
    transient = {-30.0 + 15.0 * strength_of(effects, strengths, "residual_transient"), 3.0 + 7.0 * U(rng2), 0, true};
    std::snprintf(buf, sizeof buf, "; transient %.1f ms at %.1f dB", transient.duration_ms, transient.level_db);
    hc.summary += buf;
  }

  const std::size_t pre = std::size_t(opt.pre_roll_s * fs), frames = std::size_t(opt.duration_s * fs);
  std::normal_distribution<double> N(0.0, 1.0);
  std::exponential_distribution<double> E(1.0);
  for (std::size_t s = 0; s < S; ++s) {
    ModalModel m;
    const double hold = 0.3 + 0.7 * U(rng);
    for (std::size_t n = 0; n < hc.object.modes.size(); ++n) {
      Mode mode = hc.object.modes[n];
      mode.amp *= scale * hc.strike_gain[s];
      if (support_mean > 0.0) mode.decay_per_s += hold * support_mean * E(rng);
      if (std::find(doublets.begin(), doublets.end(), n) != doublets.end()) {
        Mode hi = mode;
        mode.freq_hz -= 0.5 * split_hz;
        hi.freq_hz += 0.5 * split_hz;
        const double norm = std::hypot(1.0 - balance, balance);
        mode.amp *= (1.0 - balance) / norm;
        hi.amp *= balance / norm;
        m.modes.push_back(hi);
      }
      m.modes.push_back(mode);
    }
    Excitation e;
    if (tau_hard > 0.0) {
      e.shape = PulseShape::raised_cosine;
      e.contact_s = tau_hard * std::pow(hc.strike_gain[s] / gmax, -p);
    }
    drop_modes_at_or_above(m, 0.5 * fs);
    std::vector<float> y = render_bank(m, e, fs, frames);
    reverb.seed = seed * 131u + s;  // separate streams: one seed would correlate the two noises
    transient.seed = reverb.seed ^ 0x5851f42d4c957f2dULL;
    add_reverb_and_transient(y, fs, reverb, transient);
    Recording r;
    r.name = "strike" + std::to_string(s + 1);
    r.sample_rate_hz = fs;
    r.samples.assign(pre + frames, 0.0f);
    for (std::size_t i = 0; i < frames; ++i) r.samples[pre + i] = y[i];
    for (float& v : r.samples) v = float(double(v) + sigma * N(rng));
    hc.recordings.push_back(std::move(r));
  }
  return hc;
}

}  // namespace ms::audit
