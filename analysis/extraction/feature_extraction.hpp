// Modal features (freq_hz, decay_per_s, amp) of one impact recording.
//
// Method (chosen over Ren et al.'s spectrogram peak fitting because it resolves modes closer than a
// spectrogram bin and meets the 0.05 % / 3 % accuracy goals): high-resolution sub-band ESPRIT.
//  1. noise sigma from the median periodogram of the last quarter, plus per-band levels where the
//     noise is coloured (noise_floor.hpp);
//  2. onset from the energy rise (onset.hpp); the onset is the time origin of every amplitude;
//  3. one FFT of the decaying part, split into bands (subband.hpp): narrow bands (fine resolution,
//     whole duration) for slowly decaying modes and wide bands over the first tens of milliseconds
//     for fast ones (the narrow bands' mask kernels would swallow them); ESPRIT per band with the
//     model order from the eigenvalues against the known band noise (esprit.hpp);
//  4. all candidates refined jointly on the full-band signal by variable-projection Levenberg-Marquardt
//     with closed-form Gram matrices (damped_fit.hpp), which also fixes the amplitudes; pairs that
//     cancel each other (an ill-posed fit of crowded fast modes) are dropped;
//  5. greedy damped-sinusoid pursuit on the residual (damped_pursuit.hpp): the best-matching atom is
//     added and refit with its spectral neighbours, until nothing stands out of the noise;
//  6. Sterling et al.'s clean-up: drop stationary hum (decay below hum_decay_per_s) and modes whose
//     energy does not stand min_snr_db above the noise; refit the survivors;
//  7. optionally (low_band_restart, CLI --thorough) a second start for the crowded low band;
//  8. optionally (max_attack_skip_s) a restart after attack noise the modes cannot explain;
//  9. every mode's error bars: the Cramer-Rao bound at the fitted values (mode_precision.hpp).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/extraction/mode_precision.hpp"
#include "synthesis/modal_model.hpp"

namespace ms {

struct ExtractOptions {
  double hum_decay_per_s = 0.1;  // slower decays are stationary hum, not the impact
  double min_snr_db = 12.0;      // mode energy over noise variance (matched-filter SNR)
  double min_freq_hz = 20.0;
  // A decay faster than this (the mode is gone within ~0.5 ms) is the strike's contact transient,
  // not a resonance; the test impacts go up to 500 1/s.
  double max_decay_per_s = 2000.0;
  // No recording resolves more than this below its peak: noiseless synthetic input otherwise has a
  // floor of float rounding, and the contact transient is then "explained" by hundreds of modes.
  double max_dynamic_range_db = 90.0;
  // Samples right after the onset are the contact itself (a finite strike lasts ~0.1-2 ms) and are
  // not modal; fitting starts this long after the onset and amplitudes are extrapolated back to it.
  double skip_contact_s = 0.0;  // 0 for ideal impulses; the CLI defaults to 0.5 ms
  // Noise at the attack the modes cannot explain (a residual burst of the strike, a contact longer
  // than skip_contact_s): when the first fit's residual over the first ms stands 10 dB above its
  // level 20-60 ms later, fitting restarts after it, up to this long after the onset. 0: off (ideal
  // impulses, where every early sample is modal); the CLI and the audit default to 20 ms.
  double max_attack_skip_s = 0.0;
  // A room tail (broadband noise decaying after the strike) is measured and candidates are weighed
  // against it (noise_envelope.hpp); false: against the stationary floor only, as before it existed.
  bool room_tail = true;
  double max_duration_s = 4.0;   // analysis window after the onset
  double narrow_band_hz = 250.0; // core width of the narrow bands
  double wide_band_hz = 2000.0;  // core width of the wide bands
  double wide_window_s = 0.08;   // data used by the wide bands (fast modes)
  double fast_decay_per_s = 60.0;  // wide-band candidates at least this fast are kept
  // Wide bands see few samples per fast mode: a lower eigenvalue threshold (x noise edge) keeps the
  // weaker fast poles as candidates; the audibility check and the joint fit sort them out.
  double fast_threshold_factor = 2.0;
  int pursuit_atoms = 16;          // at most this many modes added by the residual pursuit
  // A second start for the heavily damped modes below 700 Hz (rebuilt by pursuit, refit, kept if the
  // penalised fit improves): finds ~1.6 % more modes on crowded impacts for ~70 % more time.
  bool low_band_restart = false;
  int refine_iterations = 6;
};

struct ExtractedFeatures {
  double sample_rate_hz = 0.0;
  double onset_s = 0.0;
  double noise_sigma = 0.0;     // white-noise standard deviation (full scale = 1)
  double noise_floor_db = 0.0;  // 20 log10(noise_sigma), dB re full scale
  double attack_skip_s = 0.0;   // fitting started this long after the onset (contact + attack noise)
  std::vector<Mode> modes;      // ascending frequency; phase relative to the onset
  // Per mode (same order): the Cramer-Rao standard deviations at the fitted values under the
  // measured noise (mode_precision.hpp), the error bars an efficient estimator would have.
  std::vector<ModePrecision> precision;
};

// Why a recording cannot be analysed (silent, clipped, too short), or nothing when it can.
std::optional<std::string> recording_problem(const std::vector<float>& samples, double sample_rate_hz);

// The modes of one mono recording. Call recording_problem first; a recording it rejects gives an
// empty result rather than an exception.
ExtractedFeatures extract_features(const std::vector<float>& samples, double sample_rate_hz,
                                   const ExtractOptions& options = {});

}  // namespace ms
