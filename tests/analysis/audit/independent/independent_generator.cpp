#include "independent_generator.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>

#include "independent_burst.hpp"
#include "independent_dsp.hpp"

namespace ms::indep {

std::vector<std::string> independent_effects() {
  return {"support_damping", "damping_law",        "mode_doublet", "contact_duration",
          "noise_floor",     "reverberation",      "residual_transient", "hit_position"};
}

namespace {

using Uniform = std::uniform_real_distribution<double>;

// One random stream per purpose, so that hiding one effect leaves every other draw of the case as it was.
std::mt19937_64 stream(std::uint64_t seed, std::uint32_t purpose) {
  std::seed_seq seq{std::uint32_t(seed), std::uint32_t(seed >> 32), purpose, 0x1d3cu};
  return std::mt19937_64(seq);
}
enum Purpose : std::uint32_t { kObject = 1, kStrikes, kJitter, kNoise, kEffectBase = 100 };

// v with `digits` decimals (or, with general, significant digits), for the one-line summary.
std::string num(double v, int digits, bool general = false) {
  std::ostringstream out;
  if (!general) out << std::fixed;
  out << std::setprecision(digits) << v;
  return out.str();
}

double db_to_amp(double db) { return std::pow(10.0, db / 20.0); }

double shape(const ObjectMode& m, double x) { return std::sin(m.wavenumber * x + m.shape_phase_rad); }

// The hidden effects' parameters, drawn once per case.
struct Hidden {
  double u_support = -1, u_law = -1, u_doublet = -1, u_contact = -1, u_noise = -1, u_room = -1, u_burst = -1,
         u_hit = -1;  // strength, or -1 when not hidden
};

Hidden read_effects(const std::vector<std::string>& effects, const std::vector<double>& strengths) {
  if (effects.size() != strengths.size()) throw std::invalid_argument("one strength per hidden effect");
  Hidden h;
  const std::vector<std::string> all = independent_effects();
  double* slot[] = {&h.u_support, &h.u_law, &h.u_doublet, &h.u_contact, &h.u_noise, &h.u_room, &h.u_burst, &h.u_hit};
  for (std::size_t i = 0; i < effects.size(); ++i) {
    const auto it = std::find(all.begin(), all.end(), effects[i]);
    if (it == all.end()) throw std::invalid_argument("unknown effect '" + effects[i] + "'");
    if (!(strengths[i] >= 0.0 && strengths[i] <= 1.0)) throw std::invalid_argument("strength must lie in [0, 1]");
    double& u = *slot[it - all.begin()];
    if (u >= 0.0) throw std::invalid_argument("effect '" + effects[i] + "' given twice");
    u = strengths[i];
  }
  return h;
}

// Modes log-uniform between f_lo and f_hi, nearest at least 1.5 % and 10 Hz apart; Rayleigh damping
// or the plateau; shapes sin(k x + theta) with k = pi sqrt(f / f_lo), the reference point off every
// mode's nodal lines (|shape| >= 0.3 there).
void draw_object(IndependentCase& c, const Hidden& h) {
  std::mt19937_64 rng = stream(c.seed, kObject);
  Uniform U(0.0, 1.0);
  const int count = 15 + int(rng() % 26);
  const double f_lo = 150.0 + 250.0 * U(rng), f_hi = 4500.0 + 4500.0 * U(rng);
  std::vector<double> freqs;
  for (int tries = 0; int(freqs.size()) < count && tries < 20000; ++tries) {
    const double f = f_lo * std::pow(f_hi / f_lo, U(rng));
    bool apart = true;
    for (double g : freqs) apart &= std::abs(f - g) >= std::max(0.015 * std::min(f, g), 10.0);
    if (apart) freqs.push_back(f);
  }
  std::sort(freqs.begin(), freqs.end());
  c.damping_a_per_s = 0.5 + 3.5 * U(rng);
  const double d5k = 8.0 + 32.0 * U(rng);
  c.damping_b_per_s_hz2 = (d5k - c.damping_a_per_s) / (5000.0 * 5000.0);
  if (h.u_law >= 0.0) c.plateau_hz = freqs.back() / std::sqrt(0.5 + 3.5 * h.u_law);
  c.reference_x = 0.2 + 0.6 * U(rng);
  for (double f : freqs) {
    ObjectMode m;
    m.freq_hz = f;
    const double f2 = c.plateau_hz > 0.0 ? f * f / (1.0 + std::pow(f / c.plateau_hz, 2)) : f * f;
    m.decay_per_s = c.damping_a_per_s + c.damping_b_per_s_hz2 * f2;
    m.weight = db_to_amp(-24.0 * U(rng));
    m.wavenumber = std::numbers::pi * std::sqrt(f / f_lo);
    do m.shape_phase_rad = 2.0 * std::numbers::pi * U(rng);
    while (std::abs(shape(m, c.reference_x)) < 0.3);
    c.object.push_back(m);
  }
  c.summary = "seed " + std::to_string(c.seed) + ": " + std::to_string(freqs.size()) + " modes " + num(freqs.front(), 0) +
              "-" + num(freqs.back(), 0) + " Hz, d = " + num(c.damping_a_per_s, 2) + " + " +
              num(c.damping_b_per_s_hz2, 3, true) + " f^2";
  if (c.plateau_hz > 0.0) c.summary += " / (1 + (f/" + num(c.plateau_hz, 0) + ")^2) [damping_law]";
}

double median_decay(const std::vector<ObjectMode>& object) {
  std::vector<double> d;
  for (const auto& m : object) d.push_back(m.decay_per_s);
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(d.size() / 2), d.end());
  return d[d.size() / 2];
}

// Mid-band wavenumber: the mode at the geometric middle of the object's range.
double mid_wavenumber(const std::vector<ObjectMode>& object) {
  return std::sqrt(object.front().wavenumber * object.back().wavenumber);
}

}  // namespace

IndependentCase generate_independent_case(std::uint64_t seed, const std::vector<std::string>& effects,
                                          const std::vector<double>& strengths, const IndependentOptions& opt) {
  const Hidden h = read_effects(effects, strengths);
  IndependentCase c;
  c.seed = seed;
  c.effects = effects;
  c.strengths = strengths;
  const double fs = opt.sample_rate_hz;
  draw_object(c, h);
  const std::size_t n_modes = c.object.size();
  Uniform U(0.0, 1.0);

  // Strikes: count, length, gains stratified over the spread (hardest at 0 dB), pre-rolls.
  std::mt19937_64 srng = stream(seed, kStrikes);
  const std::size_t strikes = 6 + srng() % 5;
  c.duration_s = 1.0 + 0.9 * U(srng);
  const double spread_db = 17.0 + 6.0 * U(srng);
  // The hardest at 0 dB, the softest at -spread, the others stratified in between, in random order.
  std::vector<double> gains_db = {0.0, -spread_db};
  for (std::size_t k = 0; k + 2 < strikes; ++k) gains_db.push_back(-spread_db * (double(k) + U(srng)) / double(strikes - 2));
  std::shuffle(gains_db.begin(), gains_db.end(), srng);
  c.strikes.resize(strikes);
  std::vector<std::size_t> frames(strikes);
  for (std::size_t s = 0; s < strikes; ++s) {
    c.strikes[s].gain_db = gains_db[s];
    c.strikes[s].pre_roll_frames = std::size_t((0.005 + 0.035 * U(srng)) * fs);
    frames[s] = std::size_t((c.duration_s + 0.1 * U(srng)) * fs);
    c.strikes[s].hit_x = c.reference_x;
  }
  double softest_db = 0.0;
  for (const auto& st : c.strikes) softest_db = std::min(softest_db, st.gain_db);
  c.summary += "; " + std::to_string(strikes) + " strikes x " + num(c.duration_s, 2) + " s over " + num(-softest_db, 1) + " dB";

  // Jitter, always: every strike meets every mode a little differently.
  std::mt19937_64 jrng = stream(seed, kJitter);
  c.jitter_db = 1.0 + 2.0 * U(jrng);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (auto& st : c.strikes)
    for (std::size_t n = 0; n < n_modes; ++n) st.jitter_db.push_back(c.jitter_db * normal(jrng));
  c.summary += "; jitter " + num(c.jitter_db, 2) + " dB";

  // Effects drawn each from its own stream.
  auto effect_rng = [&](std::uint32_t k) { return stream(seed, kEffectBase + k); };
  if (h.u_hit >= 0.0) {
    std::mt19937_64 r = effect_rng(7);
    const double width = (0.8 + 1.2 * h.u_hit) / mid_wavenumber(c.object);
    // Stratified over the region (a player moves about it), in random order.
    std::vector<double> spots;
    for (std::size_t s = 0; s < strikes; ++s) spots.push_back((double(s) + U(r)) / double(strikes) - 0.5);
    std::shuffle(spots.begin(), spots.end(), r);
    for (std::size_t s = 0; s < strikes; ++s) c.strikes[s].hit_x = c.reference_x + width * spots[s];
    c.summary += "; hit points over " + num(width, 3) + " units (mid-mode phase " + num(0.8 + 1.2 * h.u_hit, 2) +
                 " rad) [hit_position]";
  }
  std::vector<std::vector<double>> extra_decay(strikes, std::vector<double>(n_modes, 0.0));
  if (h.u_support >= 0.0) {
    std::mt19937_64 r = effect_rng(0);
    const double scale = (1.0 + 4.0 * h.u_support) * median_decay(c.object);
    const double hand_x = U(r), hand_width = 1.0 / mid_wavenumber(c.object);
    double mean = 0.0;
    for (std::size_t s = 0; s < strikes; ++s) {
      const double grip = 0.15 + 0.85 * U(r), x = hand_x + hand_width * (U(r) - 0.5);
      for (std::size_t n = 0; n < n_modes; ++n) {
        extra_decay[s][n] = scale * grip * std::pow(shape(c.object[n], x), 2);
        mean += extra_decay[s][n] / double(strikes * n_modes);
      }
    }
    c.summary += "; hand damping scale " + num(scale, 2) + " 1/s, mean " + num(mean, 2) + " 1/s [support_damping]";
  }
  std::vector<std::size_t> doublets;
  double split_hz = 0.0, split_angle = 0.0;
  std::vector<double> doublet_decay_factor;
  if (h.u_doublet >= 0.0) {
    std::mt19937_64 r = effect_rng(2);
    split_hz = 2.0 + 4.0 * h.u_doublet;
    split_angle = (30.0 + 30.0 * U(r)) * std::numbers::pi / 180.0;
    std::vector<std::size_t> candidates;
    for (std::size_t n = 0; n < n_modes; ++n)
      if (c.object[n].freq_hz < 3000.0) candidates.push_back(n);
    // Slow modes first (a split shows as beats only while the mode rings), then the strong ones.
    std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
      const bool sa = c.object[a].decay_per_s < 11.5, sb = c.object[b].decay_per_s < 11.5;  // T60 > 0.6 s
      if (sa != sb) return sa;
      return c.object[a].weight * std::abs(shape(c.object[a], c.reference_x)) >
             c.object[b].weight * std::abs(shape(c.object[b], c.reference_x));
    });
    const std::size_t count = std::min<std::size_t>(U(r) < 0.5 ? 1 : 2, candidates.size());
    doublets.assign(candidates.begin(), candidates.begin() + std::ptrdiff_t(count));
    for (std::size_t i = 0; i < 2 * count; ++i) doublet_decay_factor.push_back(0.9 + 0.2 * U(r));
    c.summary += "; " + std::to_string(count) + " doublet(s) split " + num(split_hz, 2) + " Hz [mode_doublet]";
  }
  double contact_soft_s = 0.0, contact_exponent = 0.0;
  ForceShape contact_shape = ForceShape::impulse;
  if (h.u_contact >= 0.0) {
    std::mt19937_64 r = effect_rng(3);
    const ForceShape shapes[] = {ForceShape::hann, ForceShape::half_sine, ForceShape::hertz};
    contact_shape = shapes[r() % 3];
    contact_soft_s = (0.4 + 1.1 * h.u_contact) * 1e-3;
    contact_exponent = 0.2 + 0.3 * h.u_contact;
    for (auto& st : c.strikes)
      st.contact = {contact_shape, contact_soft_s * std::pow(db_to_amp(st.gain_db - softest_db), -contact_exponent)};
    c.summary += "; " + shape_name(contact_shape) + " contact " + num(contact_soft_s * 1e3, 2) + " ms (softest) x gain^-" +
                 num(contact_exponent, 2) + " [contact_duration]";
  }
  std::mt19937_64 nrng = stream(seed, kNoise);
  c.noise_below_db = 80.0 + 15.0 * U(nrng);
  double noise_corner_hz = 300.0 + 2700.0 * U(nrng);
  if (h.u_noise >= 0.0) {
    std::mt19937_64 r = effect_rng(4);
    c.noise_below_db = 60.0 - 20.0 * h.u_noise;
    noise_corner_hz = 300.0 + 2700.0 * U(r);
    c.summary += "; noise " + num(c.noise_below_db, 1) + " dB below the strongest mode, corner " + num(noise_corner_hz, 0) +
                 " Hz [noise_floor]";
  }
  std::vector<double> room_ir;
  if (h.u_room >= 0.0) {
    std::mt19937_64 r = effect_rng(5);
    const double mid = 0.3 + 0.7 * U(r);
    c.room.rt60_s = {mid * (1.0 + 0.3 * U(r)), mid, mid * (0.7 + 0.25 * U(r)), mid * (0.4 + 0.3 * U(r))};
    c.room.drr_db = 8.0 - 10.0 * h.u_room;
    c.room.predelay_s = (1.5 + 4.5 * U(r)) * 1e-3;
    c.has_room = true;
    room_ir = room_impulse_response(c.room, fs, r());
    c.summary += "; room RT60 " + num(c.room.rt60_s[0], 2) + "/" + num(c.room.rt60_s[1], 2) + "/" + num(c.room.rt60_s[2], 2) +
                 "/" + num(c.room.rt60_s[3], 2) + " s, DRR " + num(c.room.drr_db, 1) + " dB [reverberation]";
  }
  BurstSpec burst_band;
  double burst_level_db = 0.0;
  std::mt19937_64 burst_rng = effect_rng(6);
  if (h.u_burst >= 0.0) {
    burst_band.low_hz = 300.0 + 1200.0 * U(burst_rng);
    burst_band.high_hz = std::min(4000.0 + 8000.0 * U(burst_rng), 0.45 * fs);
    burst_band.duration_s = (4.0 + 11.0 * U(burst_rng)) * 1e-3;
    burst_level_db = -25.0 + 15.0 * h.u_burst;
    c.summary += "; burst " + num(burst_band.duration_s * 1e3, 1) + " ms " + num(burst_band.low_hz, 0) + "-" +
                 num(burst_band.high_hz, 0) + " Hz at " + num(burst_level_db, 1) + " dB re the modes [residual_transient]";
  }

  // Each strike's modes: gain x weight x shape at the hit point x jitter; hand damping; doublets split.
  for (std::size_t s = 0; s < strikes; ++s) {
    StrikeTruth& st = c.strikes[s];
    for (std::size_t n = 0; n < n_modes; ++n) {
      const ObjectMode& om = c.object[n];
      const double amp = db_to_amp(st.gain_db + st.jitter_db[n]) * om.weight * shape(om, st.hit_x);
      const double decay = om.decay_per_s + extra_decay[s][n];
      const auto d = std::find(doublets.begin(), doublets.end(), n);
      if (d == doublets.end()) {
        st.modes.push_back({om.freq_hz, decay, amp});
        continue;
      }
      const std::size_t k = std::size_t(d - doublets.begin());
      st.modes.push_back({om.freq_hz - 0.5 * split_hz, decay * doublet_decay_factor[2 * k], amp * std::cos(split_angle)});
      st.modes.push_back({om.freq_hz + 0.5 * split_hz, decay * doublet_decay_factor[2 * k + 1], amp * std::sin(split_angle)});
    }
  }
  // Scale: the hardest strike's strongest mode at 0.2 of full scale (checked against clipping below).
  double strongest = 0.0;
  for (const auto& st : c.strikes)
    for (const auto& m : st.modes) strongest = std::max(strongest, std::abs(m.amp));
  double scale = 0.2 / strongest;

  std::vector<std::vector<double>> wet(strikes);
  double peak = 0.0;
  for (std::size_t s = 0; s < strikes; ++s) {
    StrikeTruth& st = c.strikes[s];
    std::vector<double> y = render_modes(st.modes, st.contact, fs, frames[s]);
    if (h.u_burst >= 0.0) {
      BurstSpec b = burst_band;
      const std::size_t span = std::size_t(b.duration_s * fs);
      b.rms = rms_of(y, 0, span) * db_to_amp(burst_level_db + 1.5 * normal(burst_rng));
      const std::vector<double> burst = attack_burst(b, fs, burst_rng);
      for (std::size_t i = 0; i < burst.size() && i < y.size(); ++i) y[i] += burst[i];
      st.burst_rms = b.rms;
    }
    if (!room_ir.empty()) y = convolve_fft(y, room_ir, y.size());
    for (double v : y) peak = std::max(peak, std::abs(v));
    wet[s] = std::move(y);
  }
  // Nothing may clip: strikes on one object with a room can sum above their strongest mode.
  const double clip_guard = std::min(1.0, 0.9 / (peak * scale));
  scale *= clip_guard;
  const double noise_rms = 0.2 * clip_guard * db_to_amp(-c.noise_below_db);
  for (std::size_t s = 0; s < strikes; ++s) {
    StrikeTruth& st = c.strikes[s];
    for (auto& m : st.modes) m.amp *= scale;
    st.burst_rms *= scale;
    st.noise_rms = noise_rms;
    const std::vector<double> noise = tilted_noise(st.pre_roll_frames + frames[s], noise_rms, noise_corner_hz, fs, nrng);
    audit::Recording rec;
    rec.name = "strike" + std::to_string(s + 1);
    rec.sample_rate_hz = fs;
    rec.samples.resize(noise.size());
    for (std::size_t i = 0; i < noise.size(); ++i) {
      const double dry = i >= st.pre_roll_frames ? wet[s][i - st.pre_roll_frames] * scale : 0.0;
      rec.samples[i] = float(dry + noise[i]);
    }
    c.recordings.push_back(std::move(rec));
  }
  return c;
}

}  // namespace ms::indep
