// Analytic reference objects, so that stimuli exist without a finite-element mesh.
// Each returns eigenvalues lambda0 = omega^2 [(rad/s)^2] for a specific modulus E/rho = 1 m^2/s^2,
// and the mode shape at the hit point (mass-normalised, so gains are comparable across modes).
// lambda = gamma * lambda0 for a material with E/rho = gamma.
#pragma once
#include <vector>

namespace ms {

struct ObjectModes {
  std::vector<double> lambda0;  // ascending
  std::vector<std::vector<double>> gains;  // gains[h][n]: mode shape n at hit point h
  std::vector<int> circumferential_order;  // plates: nodal diameters (>=1 is a degenerate pair); bars: 0
};

// Free-free Euler-Bernoulli bar of rectangular section: lambda0_n = (beta_n L)^4 h^2 / (12 L^4),
// cos(beta L) cosh(beta L) = 1. hit_positions in [0, 1] along the bar.
ObjectModes free_free_bar(double length_m, double thickness_m, const std::vector<double>& hit_positions,
                          double max_lambda0, std::size_t max_modes);

// The n-th root (n >= 1) of cos(x) cosh(x) = 1, x > 0: 4.7300, 7.8532, 10.9956, ...
double free_bar_root(int n);

// Free circular Kirchhoff plate (radius a, thickness h, Poisson nu):
// omega = (k^2 / a^2) sqrt(D / (rho h)), D = E h^3 / (12 (1 - nu^2)), k from the free-edge
// frequency equation (Leissa 1969, eq. 2.15). hit_radii in [0, 1) of the radius, angle 0.
// Modes with k > 600 (beyond ~90,000 modes) are not computed.
ObjectModes free_circular_plate(double radius_m, double thickness_m, double poisson,
                                const std::vector<double>& hit_radii, double max_lambda0,
                                std::size_t max_modes);

// Roots k (ascending) of the free-plate frequency equation for n nodal diameters, k in (0.5, k_max].
std::vector<double> free_plate_roots(int n, double poisson, double k_max);

}  // namespace ms
