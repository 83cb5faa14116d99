// ESPRIT (Roy & Kailath) for a complex sum of damped exponentials y[n] = sum_k c_k z_k^n + noise,
// in covariance form: R = H^H H of the Hankel data matrix (built in O(L m) by a rank-1 recursion),
// model order from R's eigenvalues against the known noise level, poles from the shift invariance.
#pragma once
#include <complex>
#include <cstddef>
#include <vector>

namespace ms {

struct EspritOptions {
  std::size_t window = 48;        // Hankel columns m (pencil length); order < window - 1
  std::size_t max_order = 40;     // upper bound on the number of poles
  // Noise eigenvalue level per Hankel row: E|noise|^2 of the *loudest* noise frequency (coloured
  // noise after band filtering). Eigenvalues above threshold_factor * rows * noise_power are signal.
  double noise_power = 0.0;
  double threshold_factor = 4.0;
  // > 0: the noise is also at least this times the median eigenvalue per row (most of the window's
  // eigenvalues are noise when the order is small). Under a room's tail, which follows the modes'
  // spectrum, the band's own level is what a candidate must stand out of, not the broadband one.
  double own_noise_factor = 0.0;
};

// Poles z_k (complex, |z| < 1 for decaying modes), strongest first. Empty when y is too short.
std::vector<std::complex<double>> esprit(const std::complex<double>* y, std::size_t length,
                                         const EspritOptions& options);

}  // namespace ms
