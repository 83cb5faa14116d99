// Noise floor of a recording under the additive white Gaussian noise model (Sterling et al. 2019):
// the median of the Hann-windowed periodogram of the recording's last quarter (where the impact has
// mostly died away and the surviving modes occupy few bins), divided by ln 2 (median of a chi-square
// with 2 degrees of freedom relative to its mean).
#pragma once
#include <cstddef>
#include <vector>

namespace ms {

// Standard deviation of the white noise in x (same units as the samples).
double estimate_noise_sigma(const std::vector<double>& x);

// 20 log10(sigma), i.e. the noise RMS in dB relative to full scale 1.0 (-inf for 0 -> -400).
double noise_floor_db(double sigma);

}  // namespace ms
