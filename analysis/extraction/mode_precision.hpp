// How precisely a recording determines its modes: the Cramer-Rao lower bound of every fitted
// parameter under white Gaussian noise, from the Fisher information J^T J / sigma^2 of the joint
// damped-sinusoid model (damped_fit.hpp's closed-form Gram, so no pass over the samples).
//
// Why: a fit reports numbers, a mature fit reports their error bars. An isolated, slowly decaying
// mode at 60 dB SNR is pinned to a hundredth of a hertz; a heavily damped mode overlapping its
// neighbours (Q near 1) may not be determined to within tens of hertz by ANY unbiased estimator.
// The bound is what an efficient estimator reaches; the extraction's errors are tested against it.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/extraction/damped_fit.hpp"

namespace ms {

struct ModePrecision {
  // Standard deviations; infinite where the data do not determine the parameter at all (the
  // Fisher information is singular in that direction, e.g. two coincident poles).
  double freq_sd_hz = 0.0;
  double decay_sd_per_s = 0.0;
  double amp_sd = 0.0;  // of the initial amplitude |b| (absolute, same unit as amp)
};

// Bounds for `components` fitted to `frames` samples at sample_rate_hz with white noise of standard
// deviation noise_sigma. Amplitudes are those at n = 0; amp_origin_offset moves them to n = -offset
// (the extraction reports amplitudes at the onset, before the skipped contact), which also carries
// the decay's uncertainty into the amplitude's.
std::vector<ModePrecision> mode_precision(const std::vector<DampedComponent>& components, std::size_t frames,
                                          double sample_rate_hz, double noise_sigma,
                                          double amp_origin_offset = 0.0);

}  // namespace ms
