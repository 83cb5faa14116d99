// Log-likelihood of the exponentially-modified-Gaussian damping model (Sterling et al. 2019, eq. 1.7):
//   p(c | lambda) = (eta/2) exp((eta/2)(2 c(lambda) + eta sigma^2 - 2c)) erfc(s),
//   s = (c(lambda) + eta sigma^2 - c) / (sqrt 2 sigma),
// in physical units, and in the well-scaled parametrisation the optimiser uses (with gradient and Hessian).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "analysis/damping/damping_features.hpp"
#include "synthesis/damping_law.hpp"

namespace ms {

// Up to 3 law parameters + log sigma + log eta. (Dynamic size: a fixed-capacity Eigen type trips
// GCC 12's -Warray-bounds under AVX; the allocations are per evaluation, not per point.)
using EmgVector = Eigen::VectorXd;
using EmgMatrix = Eigen::MatrixXd;

// Sterling's damping value c = 2d of `law` at eigenvalue lambda [(rad/s)^2]; omega^(2 a3) = lambda^a3.
double damping_c_per_s(const DampingLaw& law, double lambda_rad2_s2);

// Sum over points of log p(c_i | lambda_i) [log of a density in s, i.e. per (1/s)]. sigma [1/s], eta [s].
double emg_log_likelihood(const std::vector<DampingPoint>& points, const DampingLaw& law,
                          double sigma_per_s, double eta_s);

// The data scaled to O(1): x = lambda / lambda_scale (lambda_scale = max lambda, so x in (0, 1]) and
// y = c / c_scale (c_scale = median c). Law in scaled units, with p = alpha3:
//   rayleigh  y = a + b x        theta = (a, b, log sigma', log eta')
//   powerlaw  y = b x^p          theta = (b, p, log sigma', log eta')
//   hybrid    y = a + b x^p      theta = (a, b, p, log sigma', log eta')
// Back to physical: alpha1 = c_scale a, alpha2 = c_scale b / lambda_scale^p, sigma = c_scale sigma',
// eta = eta' / c_scale, loglik = loglik' - n log(c_scale) (the density of c is that of y / c_scale).
struct EmgProblem {
  DampingKind law = DampingKind::rayleigh;
  std::vector<double> x, y, log_x;
  // Per-point scale of the normal spread (empty: 1, Sterling's constant sigma). With it, point i's
  // normal part has spread sigma' noise_scale[i]: heteroscedastic measurement error (see damping_fit.hpp).
  std::vector<double> noise_scale;
  double lambda_scale = 1.0;
  double c_scale = 1.0;
};

EmgProblem make_emg_problem(const std::vector<DampingPoint>& points, DampingKind law);

// Number of law parameters: rayleigh 2, powerlaw 2, hybrid 3 (throws std::invalid_argument otherwise).
int law_param_count(DampingKind law);

// Scaled log-likelihood at theta; fills the analytic gradient / Hessian when the pointers are non-null.
double emg_loglik_scaled(const EmgProblem& problem, const EmgVector& theta, EmgVector* gradient,
                         EmgMatrix* hessian);

// Law parameters (first law_param_count entries of theta) <-> physical DampingLaw.
DampingLaw law_from_scaled(const EmgProblem& problem, const EmgVector& theta);
EmgVector scaled_from_law(const EmgProblem& problem, const DampingLaw& law);  // law part only

}  // namespace ms
