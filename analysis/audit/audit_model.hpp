// The model an audit compares with the recordings: modes (each tied to a measured track or not), a
// damping law, a gain per strike, and the extensions the named effects add (per-strike support
// damping, per-strike contact durations, doublet splits, a stationary noise floor, a room tail, an
// attack transient and per-strike hit patterns).
#pragma once
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "analysis/audit/gap_metric.hpp"
#include "analysis/audit/hit_pattern.hpp"
#include "analysis/audit/mode_matching.hpp"
#include "analysis/audit/strikes.hpp"
#include "synthesis/damping_law.hpp"
#include "synthesis/effects.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/modal_model.hpp"
#include "synthesis/room_response.hpp"

namespace ms::audit {

struct AuditMode {
  double freq_hz = 0.0;
  double decay_per_s = 0.0;
  double amp = 0.0;         // shape amplitude A_n (strike gain 1, ideal impulse)
  int track = -1;           // measured track it stands for (-1: none)
  double phase_rad = 0.0;   // at the onset, before the contact: a mode struck beyond a nodal line of
                            // its shape (or heard beyond one) starts inverted (pi)
  Doublets doublet;         // mode_doublet: f -+ split_hz/2 when split_hz > 0, `balance` of the amplitude
                            // in the upper mode (the pair keeps the mode's energy)
  double room_gain = 1.0;   // reverberation: the dry amplitude in the room over the one the measured
                            // amplitude implies, read from the spectrograms (room_fit.hpp)
  double room_answer = 1.0; // ... and the room's reverberant answer to this mode over its expectation: a
                            // room's response at one frequency is one draw of its noise (the same on every
                            // strike), so a slow mode may settle above or below its direct sound
};

struct AuditModel {
  std::vector<AuditMode> modes;
  DampingLaw law;                        // law the decays follow (when fitted from the recordings)
  bool law_fitted = true;                // false: decays come from a given parameter set
  std::vector<double> gain;              // per strike
  std::vector<std::vector<double>> extra_decay_per_s;  // support_damping: [strike][mode]
  double support_mean_per_s = 0.0;       // mean excess decay (for strikes with no measurement)
  std::vector<double> contact_s;         // contact_duration: per strike (empty: ideal impulse)
  double contact_ref_s = 0.0;            // ... tau_s = contact_ref_s (gain_s / contact_gain_ref)^-contact_exponent
  double contact_gain_ref = 1.0;
  double contact_exponent = 0.0;
  PulseShape contact_shape = PulseShape::raised_cosine;  // ... the force's shape (contact_spectrum.hpp)
  std::vector<double> noise_band_variance;  // noise_floor: white-equivalent variance per Bark band (empty: none)
  Room room;                             // reverberation: the rendering convolved with a room (room_power.hpp)
  Reverb reverb;                         // ... or, where the data prefer it, a white tail relative to each strike's direct sound
  AttackTransient transient;             // residual_transient: a white burst, likewise
  std::size_t transient_pseudo_modes = 0; // ... burst tracks the plain model had taken for modes (dropped)
  HitPattern hit;                        // hit_position: per-strike amplitude patterns beyond the gain
  std::vector<std::string> effects;      // named, in order
};

// Everything one audit looks at.
struct AuditData {
  MeasuredStrikes measured;
  std::vector<ModeTrack> tracks;
  // Strike-to-strike variation: mean over strikes of the gap between the strike and the loudest
  // strike scaled to its energy (dB). Strikes differing only in gain give ~0: then no effect that
  // lives in the differences between strikes (support_damping, contact_duration) can be named.
  double strike_variation_db = 0.0;
  std::size_t strike_count() const { return measured.strikes.size(); }
};

// 0 .. strike_count - 1 (every strike, e.g. as the training set of an in-sample fit).
std::vector<std::size_t> all_strikes(const AuditData& data);

// The modes that sound in strike s (gain, extra decay, contact factor, doublets applied).
ModalModel strike_model(const AuditModel& model, std::size_t strike);

// How many of strike_model's modes a model mode renders, in order: a doublet two, any other one.
inline std::size_t rendered_count(const AuditMode& m) { return m.doublet.split_hz > 0.0 ? 2 : 1; }

// strike_model with the room's dry amplitudes (room_power.hpp, times each mode's room_gain) when the
// model has a room, without the modes at or above Nyquist; owner (if given) receives the model mode
// each rendered mode stands for.
ModalModel dry_strike_model(const AuditModel& model, std::size_t strike, double sample_rate_hz,
                            std::vector<std::size_t>* owner = nullptr);

// Decay of mode n in strike s (law or given decay plus support excess).
double strike_decay(const AuditModel& model, std::size_t strike, std::size_t mode);

// What strike s does to mode n beyond its gain: hit pattern x |contact factor|.
double strike_factor(const AuditModel& model, std::size_t strike, std::size_t mode);
// |Amplitude| of mode n in strike s before the strike gain: shape x strike_factor.
double amp_before_gain(const AuditModel& model, std::size_t strike, std::size_t mode);
// ... and with it: what the strike's measured track amplitude is compared with.
double strike_amp(const AuditModel& model, std::size_t strike, std::size_t mode);

// Bark spectrograms the model predicts for strike s (rendered on the data's grids, plus the expected
// power of its noises and its room); direct_energy (if given) receives sum(y^2) of the rendered modes.
// In a room the modes are rendered with their dry amplitudes (dry_strike_model); reverberant = false
// leaves out the room's reverberant part (its fit adds that in closed form).
Spectra predict_spectra(const AuditModel& model, const AuditData& data, std::size_t strike,
                        double* direct_energy = nullptr, bool reverberant = true);

// Adds the expected power of white noise of `variance` per Bark band (one value per band) on `grid`.
void add_band_noise_power(BarkSpectrogram& spec, const SpectrogramGrid& grid, const std::vector<double>& variance);

// Adds the expected band power of synthesis/effects' decaying noise (t60_s, energy_db relative to a
// direct sound of energy direct_energy) to a spectrogram on `grid` (noise starting at sample 0, held
// for hold_s). White noise fills each band's bins; a band-limited burst only bins_per_band[b] of them,
// at a density raised by its band's share (burst_bins_per_band). Returns how many frames, from the
// first, it changed (the later ones lie more than 300 dB under the noise's start).
std::size_t add_decaying_noise_power(BarkSpectrogram& spec, const SpectrogramGrid& grid, double direct_energy,
                              double t60_s, double energy_db, const std::vector<double>* bins_per_band = nullptr,
                              double hold_s = 0.0);

// Per Bark band of `grid`: its bins, each weighted by the band's |H|^2 / band_power_share.
std::vector<double> burst_bins_per_band(const SpectrogramGrid& grid, double low_hz, double high_hz);

// Gap of strike s between the model and the measurement.
GapMap strike_gap(const AuditModel& model, const AuditData& data, std::size_t strike);

// Mean gap over the given strikes (all when empty).
double mean_gap(const AuditModel& model, const AuditData& data, const std::vector<std::size_t>& strikes = {});

// The strike_variation_db of a set of strikes.
double strike_variation(const MeasuredStrikes& measured);

// Per-strike gain from the strike's own measured track amplitudes (median log ratio against the
// model's amplitudes, contact factor included): the one latent every model has.
void fit_gain(AuditModel& model, const AuditData& data, std::size_t strike);
// ... with strike_factor(model, strike, n) given for every mode n (factor.size() == modes), for a caller
// that fits the gain again while the factors stay (they depend on neither the gain nor the shapes).
void fit_gain(AuditModel& model, const AuditData& data, std::size_t strike, std::span<const double> factor);


}  // namespace ms::audit
