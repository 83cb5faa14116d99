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

// Coloured noise: the same median periodogram per band (a third of an octave, at least 64 Hz wide),
// as the white-noise variance that would give that band's level. Where it lies within 6 dB of the
// white estimate the white estimate is used, so white noise behaves exactly as before.
struct NoiseProfile {
  std::vector<double> upper_hz;   // band upper edges, ascending
  std::vector<double> variance;   // white-equivalent variance per band
  double white_variance = 0.0;
  double variance_at(double freq_hz) const;
  double max_variance(double lo_hz, double hi_hz) const;  // over the bands overlapping [lo, hi]
};
NoiseProfile estimate_noise_profile(const std::vector<double>& x, double sample_rate_hz, double white_sigma);

// 20 log10(sigma), i.e. the noise RMS in dB relative to full scale 1.0 (-inf for 0 -> -400).
double noise_floor_db(double sigma);

}  // namespace ms
