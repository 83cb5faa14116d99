// Effects that extend the plain modal model with physics it leaves out.
//  - support damping (Zheng & James; Sterling et al.): contacts add damping per mode, the diagonal
//    of G = sum_k c_k Phi_k^T (mu I + (1 - mu) n n^T) Phi_k. Measured decay is then the material law
//    plus a one-sided excess: here a constant, per-mode values, or exponential draws (seeded).
//  - mode doublets: a degenerate pair split by imperfection into f (1 -+ split/2), which beats.
//  - background noise: stationary white Gaussian noise at a given SNR, as in a real recording room.
#pragma once
#include <cstdint>
#include <vector>

#include "synthesis/modal_model.hpp"

namespace ms {

struct SupportDamping {
  double extra_decay_per_s = 0.0;          // added to every mode
  std::vector<double> per_mode_decay_per_s;  // added to mode n (if given)
  double exponential_mean_per_s = 0.0;     // if > 0: each mode adds an Exp(mean) draw
  std::uint64_t seed = 0;
};

// Adds the support's decay to each mode (modal frequency unchanged: the extra damping is small).
void apply_support_damping(ModalModel& model, const SupportDamping& support);

struct Doublets {
  double split_rel = 0.0;      // relative split (f2 - f1)/f of each doublet
  double split_hz = 0.0;       // or an absolute split (used when > 0)
  double balance = 0.5;        // share of the amplitude in the upper mode
  int min_order = 1;           // plates: only modes with >= this many nodal diameters split
};

// Replaces each mode selected by `orders` (circumferential order >= min_order; all modes when
// orders is empty) by two modes, amplitudes (1 - balance) a and balance a.
void apply_doublets(ModalModel& model, const Doublets& doublets, const std::vector<int>& orders);

struct BackgroundNoise {
  double snr_db = 0.0;     // signal power over the whole duration / noise power
  std::uint64_t seed = 0;
  bool enabled = false;
};

// Adds white Gaussian noise so that sum(y^2)/sum(noise^2) equals snr_db (seeded, reproducible).
void add_background_noise(std::vector<float>& samples, const BackgroundNoise& noise);

}  // namespace ms
