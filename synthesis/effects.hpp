// Effects that extend the plain modal model with physics it leaves out.
//  - support damping (Zheng & James; Sterling et al.): contacts add damping per mode, the diagonal
//    of G = sum_k c_k Phi_k^T (mu I + (1 - mu) n n^T) Phi_k (contact_damping.hpp, for objects whose
//    mode shapes we have). Measured decay is then the material law plus a one-sided excess: the
//    contacts' G, and/or a constant, per-mode values, or exponential draws (seeded).
//  - mode doublets: a degenerate pair split by imperfection into f (1 -+ split/2), which beats.
//  - background noise: stationary white Gaussian noise at a given SNR, as in a real recording room.
//  - reverberation: a room tail common to all bands, white Gaussian noise decaying 60 dB in RT60
//    independently of the modes, its energy a given level relative to the direct (modal) sound.
//  - residual transient (Ren et al.'s residual): the non-modal noise of the contact, a white burst at
//    the attack decaying 60 dB within a few ms, its energy relative to the direct sound.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "synthesis/contact_damping.hpp"
#include "synthesis/modal_model.hpp"

namespace ms {

struct SupportDamping {
  double extra_decay_per_s = 0.0;          // added to every mode
  std::vector<double> per_mode_decay_per_s;  // added to mode n (if given)
  double exponential_mean_per_s = 0.0;     // if > 0: each mode adds an Exp(mean) draw
  std::uint64_t seed = 0;
  // Zheng-James contacts (contact_damping.hpp): resolving a bar or plate set adds what they give,
  // from the object's mode shapes at the contacts; apply_support_damping does not see them.
  std::vector<SupportContact> contacts = {};
  double mu = 0.0;                      // friction coefficient, [0, 1]
  std::optional<double> c_per_s = {};   // c_k of the contacts without their own
};

// Adds the support's constant, per-mode and exponential decay to each mode (modal frequency
// unchanged: the extra damping is small).
void apply_support_damping(ModalModel& model, const SupportDamping& support);

struct Doublets {
  double split_rel = 0.0;      // relative split (f2 - f1)/f of each doublet
  double split_hz = 0.0;       // or an absolute split (used when > 0)
  double balance = 0.5;        // share of the amplitude in the upper mode
  int min_order = 1;           // plates: only modes with >= this many nodal diameters split
};

// Replaces each mode selected by `orders` (circumferential order >= min_order; all modes when
// orders is empty) by two modes, amplitudes (1 - balance) a and balance a. Throws
// std::invalid_argument when a split would put a mode at or below 0 Hz.
void apply_doublets(ModalModel& model, const Doublets& doublets, const std::vector<int>& orders);

// The lowest frequency among the modes apply_doublets would split (infinity when none).
double lowest_split_freq_hz(const ModalModel& model, const Doublets& doublets, const std::vector<int>& orders);

struct BackgroundNoise {
  double snr_db = 0.0;     // signal power over the whole duration / noise power
  std::uint64_t seed = 0;
  bool enabled = false;
};

// Adds white Gaussian noise so that sum(y^2)/sum(noise^2) equals snr_db (seeded, reproducible).
void add_background_noise(std::vector<float>& samples, const BackgroundNoise& noise);

struct Reverb {
  double rt60_s = 0.0;      // tail decays 60 dB in this time
  double level_db = 0.0;    // tail energy / direct energy (dB)
  std::uint64_t seed = 0;
  bool enabled = false;
};

struct AttackTransient {
  double level_db = 0.0;     // burst energy / direct energy (dB)
  double duration_ms = 0.0;  // burst decays 60 dB in this time
  std::uint64_t seed = 0;
  bool enabled = false;
  // The burst's band (a stick's click rings in the striker's own band): both 0 = white. Its power
  // spectrum is burst_band_gain2: flat inside, falling 24 dB per octave past each edge (a 4th-order
  // Butterworth's magnitude; -3 dB at the edges); the level stays the burst's whole energy.
  double low_hz = 0.0, high_hz = 0.0;
  bool band_limited() const { return high_hz > 0.0; }
  // A burst that lasts (a rattle, a scrape) holds its level this long before it decays.
  double hold_ms = 0.0;
};

// White Gaussian noise with standard deviation sigma0 from sample 0 for hold_s, then sigma0
// exp(-ln(1000) t / t60_s) from there, sigma0 chosen so its expected energy is energy_db relative to
// sum(samples^2) as given (seeded).
void add_decaying_noise(std::vector<float>& samples, double sample_rate_hz, double t60_s, double energy_db,
                        std::uint64_t seed, double hold_s = 0.0);

// sigma0^2 of add_decaying_noise for a direct sound of energy sum(x^2) = direct_energy over n samples.
double decaying_noise_variance(double direct_energy, double sample_rate_hz, std::size_t n, double t60_s,
                               double energy_db, double hold_s = 0.0);

// The held samples of a hold (rounded to the sample) and the envelope sample i has (1 while held).
std::size_t hold_samples(double hold_s, double sample_rate_hz);
double noise_envelope(std::size_t i, std::size_t held, double decay_per_sample);

// |H(f)|^2 of a burst's band: 1 / (1 + (f / high)^8) / (1 + (low / f)^8) (no low edge when low is 0;
// 1 for white, high 0).
double burst_band_gain2(double freq_hz, double low_hz, double high_hz);

// Share of a white noise's power that a band keeps (the mean of |H|^2 up to Nyquist; 1 for white):
// the burst's variance is divided by it, so that its energy stays level_db whatever its band.
double band_power_share(double low_hz, double high_hz, double sample_rate_hz);

// Both relative to the direct sound `samples` holds when called (neither sees the other's noise).
void add_reverb_and_transient(std::vector<float>& samples, double sample_rate_hz, const Reverb& reverb,
                              const AttackTransient& transient);

}  // namespace ms
