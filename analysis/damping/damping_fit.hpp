// Fit a damping law (rayleigh / powerlaw / hybrid, Sterling's c = 2d convention) to (lambda, c) points
// from many strikes of one material, by least squares, lower bound, or EMG maximum likelihood.
//  lsq  min sum (c_i - c(lambda_i))^2 (vertical, unweighted). Rayleigh: closed form; powerlaw/hybrid:
//       variable projection (linear in alpha1, alpha2 for fixed alpha3; 1-D search over alpha3).
//  lb   min sum (c_i - c(lambda_i)) subject to c(lambda_i) <= c_i for all i (an LP). Its optimum is a
//       supporting line of the lower convex hull: the sum equals n (mean c - line(mean lambda)), so the
//       edge of the lower hull above the mean abscissa is optimal. Rayleigh: hull of (lambda, c);
//       powerlaw: hull of (log lambda, log c) (log-distances); hybrid: hull of (lambda^alpha3, c),
//       alpha3 chosen by 1-D search minimising the LP objective.
//  emg  maximum likelihood of the exponentially modified Gaussian (Sterling et al. 2019): damped Newton
//       (exact Hessian, Levenberg shift when not concave, Armijo backtracking) on scaled parameters
//       with log sigma and log eta, started from the LB and the LSQ fits; the better optimum is kept.
//       Optionally with a spread proportional to c (DampingFitOptions::relative_noise).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "analysis/damping/damping_features.hpp"
#include "synthesis/damping_law.hpp"

namespace ms {

enum class DampingEstimator { lsq, lb, emg };

DampingEstimator parse_damping_estimator(const std::string& name);  // throws std::invalid_argument
std::string to_string(DampingEstimator estimator);

struct DampingFitOptions {
  int max_iterations = 200;        // Newton iterations per start (emg)
  // emg only. false: Sterling's model, one normal spread sigma for every point. true: the spread grows
  // in proportion to the law's value (sigma_i = sigma c(lambda_i) / median c), because measured
  // decays err in proportion to the decay (extraction from sounds: +-0.2 1/s at c = 3 1/s, +-20 1/s at
  // c = 300 1/s); one sigma is then set by the fast modes and swamps the support excess that fixes
  // alpha1. The scales come from the LB law, then once more from the fitted law; sigma is reported at
  // the median c.
  bool relative_noise = false;
  double tolerance = 1e-11;        // stop when the Newton decrement g' H^-1 g (scaled loglik) is below
};

struct DampingFit {
  DampingLaw law;  // kind, alpha1 [1/s], alpha2, alpha3 in physical units (lambda in (rad/s)^2)
  DampingEstimator estimator = DampingEstimator::lsq;
  std::optional<double> sigma_per_s;  // emg only: normal spread of c
  std::optional<double> eta_s;        // emg only: rate of the exponential excess of c
  std::optional<double> loglik;       // emg only: sum log p(c_i | lambda_i), density per (1/s)
  int iterations = 0;  // emg: Newton steps (both starts); lsq/lb: 1-D profile evaluations (0 if closed form)
  bool converged = true;
};

// Parameters estimated: law parameters (+ sigma and eta for emg). A fit needs at least this many points.
std::size_t damping_fit_param_count(DampingKind law, DampingEstimator estimator);

// Throws std::invalid_argument when points.size() < damping_fit_param_count (callers check first).
DampingFit fit_damping(const std::vector<DampingPoint>& points, DampingKind law,
                       DampingEstimator estimator, const DampingFitOptions& options = {});

}  // namespace ms
