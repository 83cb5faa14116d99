// Greedy damped-sinusoid pursuit on the residual of a fit: the early part of the residual is
// correlated (one FFT per trial decay) with e^{(-d + i w) n} atoms; the best atom above the noise is
// added and refined jointly with its spectral neighbours (damped_fit.hpp), then the next is sought.
// Why: heavily damped modes crowded at low frequencies overlap in every sub-band and defeat
// sub-band ESPRIT, but one at a time against the residual they stand out, and the neighbour refit
// separates those a first pick merged.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/extraction/damped_fit.hpp"
#include "analysis/extraction/noise_envelope.hpp"
#include "analysis/extraction/noise_floor.hpp"

namespace ms {

struct PursuitOptions {
  double window_s = 0.1;                    // early residual searched for atoms
  std::vector<double> decays_per_s{20.0, 35.0, 60.0, 100.0, 170.0, 300.0, 500.0, 850.0};
  double min_freq_hz = 20.0;
  double max_freq_hz = 20000.0;
  double noise_variance = 0.0;              // white-noise variance per sample
  const NoiseProfile* noise = nullptr;      // coloured noise (optional): per-frequency variance
  const NoiseEnvelope* tail = nullptr;      // decaying noise (optional): per-time variance
  double min_gain = 40.0;                   // atom energy over noise variance to be added
  int max_atoms = 16;
  double min_local_decay_per_s = 20.0;      // slower neighbours are held fixed in the local refit
  int refine_iterations = 15;       // a local refit is cheap; crowded clusters need the steps
};

// Adds components to `components` (already fitted to x); returns how many were added.
std::size_t damped_pursuit(const std::vector<double>& x, double sample_rate_hz,
                           std::vector<DampedComponent>& components, const PursuitOptions& options);

}  // namespace ms
