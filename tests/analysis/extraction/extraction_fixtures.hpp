// Shared synthetic impacts for the extraction tests and benchmark: seeded random modal models
// rendered by the closed-form reference renderer, plus white Gaussian noise at a given SNR.
#pragma once
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "synthesis/modal_model.hpp"
#include "synthesis/reference_renderer.hpp"

namespace ms::testing {

// 20-60 modes: frequency log-uniform in [50 Hz, 16 kHz], decay log-uniform in [0.5, 500] 1/s,
// amplitude uniform in dB over [-40, 0] (re 0.5), phase 0 (struck from rest).
inline ModalModel random_impact(std::uint64_t seed, std::size_t min_modes = 20, std::size_t max_modes = 60) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> count(min_modes, max_modes);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  ModalModel m;
  const std::size_t n = count(rng);
  for (std::size_t i = 0; i < n; ++i) {
    Mode mode;
    mode.freq_hz = 50.0 * std::pow(16000.0 / 50.0, u(rng));
    mode.decay_per_s = 0.5 * std::pow(1000.0, u(rng));
    mode.amp = 0.5 * std::pow(10.0, -40.0 * u(rng) / 20.0);
    m.modes.push_back(mode);
  }
  return m;
}

// Renders `model` (double precision) and adds white noise whose power is snr_db below the mean
// power of the whole clean signal. Returns float samples as a WAV file would hold them.
inline std::vector<float> render_noisy(const ModalModel& model, double fs, double seconds, double snr_db,
                                       std::uint64_t seed, std::size_t lead_frames = 0,
                                       double* noise_sigma = nullptr) {
  const auto frames = std::size_t(seconds * fs);
  const std::vector<double> clean = render_reference(model, {}, fs, frames);
  double power = 0.0;
  for (double v : clean) power += v * v;
  power /= double(frames);
  const double sigma = std::sqrt(power / std::pow(10.0, snr_db / 10.0));
  if (noise_sigma) *noise_sigma = sigma;
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<float> out(lead_frames + frames);
  for (std::size_t n = 0; n < out.size(); ++n)
    out[n] = float((n >= lead_frames ? clean[n - lead_frames] : 0.0) + noise(rng));
  return out;
}

}  // namespace ms::testing
