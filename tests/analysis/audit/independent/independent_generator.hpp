// A second hidden-effect generator for proving the audit, written apart from the audit's own
// generator, renderer and effect models (it uses only std, FFTW and the audit's Recording type).
//
// The clean object: 15-40 modes between 150-400 Hz and 4.5-9 kHz, nearest modes at least 1.5 % and
// 10 Hz apart (closer is a doublet); Rayleigh damping d = a + b f^2 (amplitude decay rate, 0.5-4 1/s
// at 0 Hz, 8-40 1/s at 5 kHz); mode shapes sin(k x + theta) with k proportional to sqrt(f) (bending
// waves) and every strike at one reference point; an ideal impulse; no room, no attack noise; a
// microphone noise floor 80-95 dB below the strongest mode. Always, as with real hands: 6-10 strikes
// of 1-2 s (1-1.9 s + up to 0.1 s, with 5-40 ms of noise before each), strike gains spread over 17-23 dB, and every mode's
// amplitude in every strike jittered by N(0, sigma) dB, sigma drawn per case from 1-3 dB.
//
// Hidden effects (the audit's catalog names), strength u in [0, 1] from weakest to strongest:
//  reverberation       one room for all strikes: unit direct impulse + decaying band-split noise
//                      (independent_room.hpp), mid-band RT60 0.3-1 s, DRR 8 - 10u dB, by FFT convolution
//  residual_transient  a band-limited burst per strike (independent_burst.hpp): 4-15 ms, band edges
//                      300-1500 Hz and 4-12 kHz, -25 + 15u dB re the strike's modes over the burst
//  contact_duration    Hann, half-sine or Hertz contacts of (0.4 + 1.1u) ms at the softest strike,
//                      shortening as gain^-(0.2 + 0.3u)
//  support_damping     a hand on the object at a point that moves per strike and a grip per strike:
//                      mode n's extra decay D grip_s sin^2(k_n x_hand,s + theta_n), D = (1 + 4u) x the
//                      median clean decay
//  damping_law         a loss plateau d = a + b f^2 / (1 + (f / f_c)^2), the top mode (1.5 + 3.5u)x
//                      slower than Rayleigh
//  mode_doublet        1-2 slowly decaying modes below 3 kHz split by 2 + 4u Hz
//  noise_floor         stationary tilted noise 60 - 20u dB below the strongest mode
//  hit_position        each strike at its own point of a region across which the mid-band mode's shape
//                      phase moves by 0.8 + 1.2u rad (modes move by several dB, high ones most)
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/audit/strikes.hpp"
#include "independent_modes.hpp"
#include "independent_room.hpp"

namespace ms::indep {

// The effects this generator can hide.
std::vector<std::string> independent_effects();

struct IndependentOptions {
  double sample_rate_hz = 44100.0;
};

struct ObjectMode {
  double freq_hz = 0.0;
  double decay_per_s = 0.0;   // on the case's damping law
  double weight = 0.0;        // participation x radiation, > 0
  double wavenumber = 0.0;    // k, rad per unit length
  double shape_phase_rad = 0.0;
};

// What was rendered in one strike (amplitudes at the recording's scale).
struct StrikeTruth {
  double gain_db = 0.0;             // 0 for the hardest strike
  double hit_x = 0.0;
  Contact contact;
  std::vector<double> jitter_db;    // per object mode
  std::vector<DampedMode> modes;    // as rendered: doublets split, hand damping, hit point, jitter
  std::size_t pre_roll_frames = 0;
  double noise_rms = 0.0;
  double burst_rms = 0.0;           // 0: no burst
};

struct IndependentCase {
  std::uint64_t seed = 0;
  std::vector<std::string> effects;
  std::vector<double> strengths;
  std::vector<ObjectMode> object;
  double damping_a_per_s = 0.0, damping_b_per_s_hz2 = 0.0;  // clean law d = a + b f^2
  double plateau_hz = 0.0;                                  // > 0: the damping_law effect's plateau
  double jitter_db = 0.0, duration_s = 0.0, reference_x = 0.0;
  double noise_below_db = 0.0;      // under the hardest strike's strongest mode
  bool has_room = false;
  RoomSpec room;
  std::vector<StrikeTruth> strikes;
  std::vector<audit::Recording> recordings;  // "strike1".."strikeN"
  std::string summary;                       // one line: the object and what is hidden
};

// Throws std::invalid_argument for an unknown effect, a repeated one, or a strength outside [0, 1].
IndependentCase generate_independent_case(std::uint64_t seed, const std::vector<std::string>& effects,
                                          const std::vector<double>& strengths, const IndependentOptions& options = {});

}  // namespace ms::indep
