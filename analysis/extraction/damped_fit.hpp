// Full-band least squares for a sum of real damped sinusoids x[n] ~ sum_k Re(b_k e^{s_k n}),
// s_k = (-d_k + i 2 pi f_k) / fs. The Gram matrix of the model (and of its derivatives) has a closed
// form (geometric sums with n^0..n^2 weights), so only the data projections sum_n x[n] n^p e^{s n}
// touch the samples. fit_amplitudes solves the linear problem for fixed poles; refine_poles runs a
// Levenberg-Marquardt on all poles jointly (amplitudes re-solved at each trial: variable projection).
#pragma once
#include <Eigen/Core>
#include <complex>
#include <cstddef>
#include <vector>

namespace ms {

struct DampedComponent {
  std::complex<double> s;  // per-sample pole exponent (-d + i omega) / fs
  std::complex<double> b;  // complex amplitude at n = 0; amp = |b|, phase = arg(b) + pi/2
};

// sum_{n=0}^{N-1} n^power e^{sigma n}, power 0..2 (closed form; series near sigma = 0).
std::complex<double> weighted_geometric_sum(int power, std::complex<double> sigma, std::size_t frames);

// Least-squares complex amplitudes for the given poles; returns the residual energy.
double fit_amplitudes(const std::vector<double>& x, std::vector<DampedComponent>& components);

// x[n] - sum_k Re(b_k e^{s_k n}) for n < frames (frames <= x.size()).
std::vector<double> subtract_components(const std::vector<double>& x,
                                        const std::vector<DampedComponent>& components, std::size_t frames);

// Gram matrix J^T J of the model's 4K columns per component k (rows 4k..4k+3): the derivatives by
// Re b_k, Im b_k, Re s_k, Im s_k, over n < frames, in closed form. Over the white noise variance it is
// the Fisher information of the parameters (mode_precision.hpp).
Eigen::MatrixXd pole_gram(const std::vector<DampedComponent>& components, std::size_t frames);

struct RefineOptions {
  int max_iterations = 8;
  double relative_tolerance = 1e-7;  // stop when the residual energy improves less than this
};

// Joint refinement of poles and amplitudes; returns the final residual energy.
double refine_poles(const std::vector<double>& x, std::vector<DampedComponent>& components,
                    const RefineOptions& options = {});

}  // namespace ms
