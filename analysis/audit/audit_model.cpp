#include "analysis/audit/audit_model.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/audit/contact_spectrum.hpp"
#include "analysis/audit/room_power.hpp"
#include "synthesis/effects.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/resonator_bank.hpp"

namespace ms::audit {

std::vector<std::size_t> all_strikes(const AuditData& data) {
  std::vector<std::size_t> s(data.strike_count());
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = i;
  return s;
}

double strike_decay(const AuditModel& model, std::size_t s, std::size_t n) {
  double d = model.modes[n].decay_per_s;
  if (!model.extra_decay_per_s.empty()) d += model.extra_decay_per_s[s][n];
  return d;
}

double strike_factor(const AuditModel& model, std::size_t s, std::size_t n) {
  const AuditMode& m = model.modes[n];
  const double tau = model.contact_s.empty() ? 0.0 : model.contact_s[s];
  double f = contact_gain(model.contact_shape, tau, strike_decay(model, s, n), m.freq_hz);
  if (model.hit.active()) f *= std::exp(model.hit.log_factor(s, n));
  return f;
}

double amp_before_gain(const AuditModel& model, std::size_t s, std::size_t n) {
  return model.modes[n].amp * strike_factor(model, s, n);
}

double strike_amp(const AuditModel& model, std::size_t s, std::size_t n) {
  return model.gain[s] * amp_before_gain(model, s, n);
}


ModalModel strike_model(const AuditModel& model, std::size_t s) {
  ModalModel out;
  const double tau = model.contact_s.empty() ? 0.0 : model.contact_s[s];
  Excitation e;
  e.shape = model.contact_shape;
  e.contact_s = tau;
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    const AuditMode& m = model.modes[n];
    const double d = strike_decay(model, s, n);
    double amp = m.amp * model.gain[s], phase = m.phase_rad;
    if (model.hit.active()) amp *= std::exp(model.hit.log_factor(s, n));
    if (tau > 0.0) {
      const std::complex<double> g = contact_factor(e, d, m.freq_hz);
      amp *= std::abs(g);
      phase += std::arg(g);
    }
    if (m.doublet.split_hz > 0.0) {
      // Keep the pair's energy equal to the merged mode's (tracks merge members by energy).
      const Doublets& db = m.doublet;
      const double norm = std::hypot(1.0 - db.balance, db.balance);
      out.modes.push_back({m.freq_hz - 0.5 * db.split_hz, d, amp * (1.0 - db.balance) / norm, phase});
      out.modes.push_back({m.freq_hz + 0.5 * db.split_hz, d, amp * db.balance / norm, phase});
    } else {
      out.modes.push_back({m.freq_hz, d, amp, phase});
    }
  }
  return out;
}

std::size_t add_decaying_noise_power(BarkSpectrogram& spec, const SpectrogramGrid& g, double direct_energy, double t60_s,
                                     double energy_db, const std::vector<double>* bins_per_band, double hold_s) {
  if (t60_s <= 0.0) return 0;
  // The noise's energy is relative to the direct sound over the whole strike, as synthesis adds it.
  const double var0 = decaying_noise_variance(direct_energy, g.sample_rate_hz, g.samples, t60_s, energy_db, hold_s);
  // Per bin, white noise of variance v_i gives E|X|^2 = sum_i w_i^2 v_i; v_i is var0 while held, then
  // falls by r per sample.
  const double r = std::exp(-2.0 * std::log(1000.0) / (t60_s * g.sample_rate_hz));
  const std::size_t held = hold_samples(hold_s, g.sample_rate_hz);
  // The burst and tail fits call this a few thousand times per audit: the window comes from the grid.
  const std::vector<double>& w2 = g.window_squared;
  double frame0 = 0.0, ri = 1.0;
  for (std::size_t i = 0; i < g.window; ++i, ri *= r) frame0 += w2[i] * ri;
  // r^(t0 - held) after the hold: one power, then a factor r^hop per frame (a power per frame was a
  // few per cent of a room's audit; the product drifts by ~1e-14 over a strike).
  const double per_hop = std::pow(r, double(g.hop));
  double fallen = -1.0;
  for (std::size_t f = 0; f < spec.frames; ++f) {
    const std::size_t t0 = f * g.hop;
    double level = 0.0;
    if (t0 >= held) {
      fallen = fallen < 0.0 ? std::pow(r, double(t0 - held)) : fallen * per_hop;
      level = var0 * fallen * frame0;
    } else {  // the frame meets the hold: its samples one by one, r^j from the hold's end on
      double after = 1.0;
      for (std::size_t i = 0; i < g.window; ++i) {
        const bool holding = t0 + i < held;
        level += w2[i] * var0 * (holding ? 1.0 : after);
        if (!holding) after *= r;
      }
    }
    if (!(level > 1e-30 * var0)) return f;
    for (std::size_t b = 0; b < spec.bands; ++b)
      spec.at(f, b) += level * (bins_per_band ? (*bins_per_band)[b] : double(g.band_bins[b]));
  }
  return spec.frames;
}

std::vector<double> burst_bins_per_band(const SpectrogramGrid& g, double low_hz, double high_hz) {
  std::vector<double> bins(g.bands, 0.0);
  const double share = band_power_share(low_hz, high_hz, g.sample_rate_hz);
  for (std::size_t k = 1; k < g.bin_band.size(); ++k) {
    const double f = double(k) * g.sample_rate_hz / double(g.window);
    if (g.bin_band[k] >= 0) bins[std::size_t(g.bin_band[k])] += burst_band_gain2(f, low_hz, high_hz) / share;
  }
  return bins;
}

void add_band_noise_power(BarkSpectrogram& spec, const SpectrogramGrid& g, const std::vector<double>& variance) {
  if (variance.empty()) return;
  for (std::size_t f = 0; f < spec.frames; ++f)
    for (std::size_t b = 0; b < spec.bands && b < variance.size(); ++b)
      spec.at(f, b) += variance[b] * g.window_energy * double(g.band_bins[b]);
}

ModalModel dry_strike_model(const AuditModel& model, std::size_t s, double fs, std::vector<std::size_t>* owner) {
  ModalModel modal = strike_model(model, s);
  std::vector<std::size_t> of;  // a doublet renders two modes
  for (std::size_t n = 0; n < model.modes.size(); ++n) of.insert(of.end(), rendered_count(model.modes[n]), n);
  if (model.room.enabled) {
    for (std::size_t j = 0; j < modal.modes.size(); ++j) modal.modes[j].amp *= model.modes[of[j]].room_gain;
    make_dry(modal, room_rates(model.room, fs), fs);
  }
  std::size_t j = 0;
  std::erase_if(of, [&](std::size_t) { return modal.modes[j++].freq_hz >= 0.5 * fs; });
  drop_modes_at_or_above(modal, 0.5 * fs);
  if (owner) *owner = std::move(of);
  return modal;
}

Spectra predict_spectra(const AuditModel& model, const AuditData& data, std::size_t s, double* direct_energy,
                        bool reverberant) {
  const MeasuredStrikes& ms_ = data.measured;
  std::vector<std::size_t> owner;
  const ModalModel modal = dry_strike_model(model, s, ms_.sample_rate_hz, &owner);
  const RoomRates rates = model.room.enabled ? room_rates(model.room, ms_.sample_rate_hz) : RoomRates{};
  Excitation impulse;  // the contact is already folded into amplitudes and phases
  const std::size_t samples = ms_.strikes[s].samples.size();
  const std::vector<float> y = render_bank(modal, impulse, ms_.sample_rate_hz, samples);
  Spectra spec = bark_spectra(y, ms_.grids);
  double energy = 0.0;
  for (float v : y) energy += double(v) * double(v);
  if (direct_energy) *direct_energy = energy;
  for (std::size_t r = 0; r < kResolutions; ++r) {
    if (model.room.enabled && reverberant) {
      const RoomGrid rg = room_grid(ms_.grids[r]);
      RoomFootprint fp = room_footprint(ms_.grids[r], rg, modal, &rates);
      for (RoomFootprint::ModeTerms& m : fp.modes) m.answer = model.modes[owner[m.owner]].room_answer;
      add_room_power(spec[r], ms_.grids[r], rg, fp, rates);
    }
    if (model.reverb.enabled)
      add_decaying_noise_power(spec[r], ms_.grids[r], energy, model.reverb.rt60_s, model.reverb.level_db);
    if (model.transient.enabled && model.transient.band_limited()) {
      const std::vector<double> bins = burst_bins_per_band(ms_.grids[r], model.transient.low_hz, model.transient.high_hz);
      add_decaying_noise_power(spec[r], ms_.grids[r], energy, 1e-3 * model.transient.duration_ms,
                               model.transient.level_db, &bins, 1e-3 * model.transient.hold_ms);
    } else if (model.transient.enabled) {
      add_decaying_noise_power(spec[r], ms_.grids[r], energy, 1e-3 * model.transient.duration_ms,
                               model.transient.level_db, nullptr, 1e-3 * model.transient.hold_ms);
    }
    add_band_noise_power(spec[r], ms_.grids[r], model.noise_band_variance);
  }
  return spec;
}

GapMap strike_gap(const AuditModel& model, const AuditData& data, std::size_t s) {
  return gap_map(data.measured.strikes[s].spectra, predict_spectra(model, data, s));
}

double mean_gap(const AuditModel& model, const AuditData& data, const std::vector<std::size_t>& strikes) {
  const std::vector<std::size_t> which = strikes.empty() ? all_strikes(data) : strikes;
  double sum = 0.0;
  for (std::size_t s : which) sum += strike_gap(model, data, s).gap_db;
  return which.empty() ? 0.0 : sum / double(which.size());
}

double strike_variation(const MeasuredStrikes& measured) {
  const auto energy = [](const Spectra& b) {
    double e = 0.0;
    for (double p : b[kDecay].power) e += p;
    return e;
  };
  std::size_t ref = 0;
  for (std::size_t s = 0; s < measured.strikes.size(); ++s)
    if (energy(measured.strikes[s].spectra) > energy(measured.strikes[ref].spectra)) ref = s;
  const Spectra& r = measured.strikes[ref].spectra;
  double sum = 0.0;
  for (std::size_t s = 0; s < measured.strikes.size(); ++s) {
    if (s == ref) continue;
    Spectra scaled = r;
    const double k = energy(measured.strikes[s].spectra) / std::max(energy(r), 1e-300);
    for (BarkSpectrogram& b : scaled)
      for (double& p : b.power) p *= k;
    sum += gap_map(measured.strikes[s].spectra, scaled).gap_db;
  }
  return measured.strikes.size() > 1 ? sum / double(measured.strikes.size() - 1) : 0.0;
}

namespace {

// The median over the strike's present modes of log(measured / model before gain), as the gain.
template <class Factor>
void fit_gain_with(AuditModel& model, const AuditData& data, std::size_t s, const Factor& factor) {
  std::vector<double> ratios;
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    const AuditMode& m = model.modes[n];
    if (m.track < 0 || m.amp <= 0.0) continue;
    const TrackObservation& o = data.tracks[std::size_t(m.track)].strikes[s];
    if (!o.present) continue;
    ratios.push_back(std::log(o.amp / (m.amp * factor(n))));
  }
  if (ratios.empty()) {
    model.gain[s] = 1.0;
    return;
  }
  std::nth_element(ratios.begin(), ratios.begin() + std::ptrdiff_t(ratios.size() / 2), ratios.end());
  model.gain[s] = std::exp(ratios[ratios.size() / 2]);
}

}  // namespace

void fit_gain(AuditModel& model, const AuditData& data, std::size_t s) {
  fit_gain_with(model, data, s, [&](std::size_t n) { return strike_factor(model, s, n); });
}

void fit_gain(AuditModel& model, const AuditData& data, std::size_t s, std::span<const double> factor) {
  fit_gain_with(model, data, s, [&](std::size_t n) { return factor[n]; });
}

}  // namespace ms::audit
