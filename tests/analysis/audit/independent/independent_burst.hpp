// The attack burst of the independent generator: what a strike makes besides the modes (the striker's
// own rattle, air pushed out, friction), white Gaussian noise through a 4th-order Butterworth
// high-pass at low_hz and low-pass at high_hz, under an envelope that holds for half the burst and
// falls as a half cosine to zero at duration_s.
#pragma once
#include <random>
#include <vector>

namespace ms::indep {

struct BurstSpec {
  double duration_s = 0.01;
  double low_hz = 1000.0, high_hz = 8000.0;  // band edges (-3 dB each)
  double rms = 0.1;                          // over the burst's duration
};

// duration_s * sample_rate_hz samples.
std::vector<double> attack_burst(const BurstSpec& burst, double sample_rate_hz, std::mt19937_64& rng);

}  // namespace ms::indep
