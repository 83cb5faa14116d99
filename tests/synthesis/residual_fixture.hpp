// A consistent residual for the residual tests: the power spectrogram of a decaying Gaussian noise burst.
#pragma once
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "synthesis/residual_file.hpp"

namespace ms::test {

// level * N(0, 1) * e^{-decay_per_s t} over `samples` samples, guided by `modes`.
inline ResidualSpectrogram noise_burst_residual(const std::vector<Mode>& modes, double level, double decay_per_s,
                                                std::size_t samples, std::uint64_t seed,
                                                double sample_rate_hz = 44100.0) {
  ResidualSpectrogram r;
  r.sample_rate_hz = sample_rate_hz;
  r.modes = modes;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<float> burst(samples);
  for (std::size_t n = 0; n < samples; ++n)
    burst[n] = float(level * normal(rng) * std::exp(-decay_per_s * double(n) / sample_rate_hz));
  Stft stft(r.grid);
  const std::vector<double> p = stft.power(burst);
  r.power.assign(p.begin(), p.end());
  r.frames = r.grid.frames_for(samples);
  return r;
}

}  // namespace ms::test
