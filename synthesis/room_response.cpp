#include "synthesis/room_response.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <random>

#include "synthesis/fft.hpp"

namespace ms {

double room_octave_lower_edge_hz(std::size_t band) {
  return band == 0 ? 0.0 : std::sqrt(kRoomOctaveCentresHz[band - 1] * kRoomOctaveCentresHz[band]);
}

double room_octave_upper_edge_hz(std::size_t band) {
  return band + 1 >= kRoomOctaveCentresHz.size() ? std::numeric_limits<double>::infinity()
                                                 : room_octave_lower_edge_hz(band + 1);
}

std::size_t room_octave_band(double freq_hz) {
  std::size_t band = 0;
  while (band + 1 < kRoomOctaveCentresHz.size() && freq_hz >= room_octave_lower_edge_hz(band + 1)) ++band;
  return band;
}

std::vector<float> room_impulse_response(const Room& room, double fs) {
  double longest = 0.0;
  for (double t : room.rt60_s) longest = std::max(longest, t);
  const std::size_t length = std::size_t(std::ceil(longest * fs)) + 1;
  std::vector<float> h(length, 0.0f);
  h[0] = 1.0f;
  if (length < 2) return h;
  // White noise split into octave bands by complementary masks on its spectrum; each band decays at its
  // own rate. The noise fills the whole (circular) transform, so every band stays stationary before
  // its envelope is applied.
  RealFft fft(nice_fft_size(length), RealFft::Directions::forward_and_backward);
  const std::size_t n = fft.size(), bins = n / 2 + 1;
  std::mt19937_64 rng(room.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) fft.real()[i] = gauss(rng);
  fft.forward();
  const std::vector<std::complex<double>> white(fft.spectrum(), fft.spectrum() + bins);
  std::vector<double> tail(length - 1, 0.0);
  const bool one_rate = room.rt60_s.size() == 1;
  for (std::size_t band = 0; band < (one_rate ? 1 : kRoomOctaveCentresHz.size()); ++band) {
    for (std::size_t k = 0; k < bins; ++k)
      fft.spectrum()[k] = one_rate || room_octave_band(double(k) * fs / double(n)) == band ? white[k] : 0.0;
    fft.backward();
    const double k_per_sample = std::log(1000.0) / (room.band_rt60_s(band) * fs);
    for (std::size_t i = 0; i + 1 < length; ++i)
      tail[i] += fft.real()[i] / double(n) * std::exp(-k_per_sample * double(i + 1));
  }
  double energy = 0.0;
  for (double v : tail) energy += v * v;
  const double scale = std::sqrt(std::pow(10.0, -room.drr_db / 10.0) / std::max(energy, 1e-300));
  for (std::size_t i = 0; i + 1 < length; ++i) h[i + 1] = float(scale * tail[i]);
  return h;
}

void convolve_overlap_add(std::vector<float>& samples, const std::vector<float>& ir) {
  if (samples.empty() || ir.empty()) return;
  const std::size_t taps = ir.size();
  RealFft fft(nice_fft_size(std::max<std::size_t>(2 * taps, 4096)), RealFft::Directions::forward_and_backward);
  const std::size_t n = fft.size(), bins = n / 2 + 1, block = n - taps + 1;
  std::fill(fft.real(), fft.real() + n, 0.0);
  std::copy(ir.begin(), ir.end(), fft.real());
  fft.forward();
  std::vector<std::complex<double>> response(fft.spectrum(), fft.spectrum() + bins);
  for (std::complex<double>& c : response) c /= double(n);  // backward() multiplies by n
  std::vector<double> out(samples.size(), 0.0);
  for (std::size_t start = 0; start < samples.size(); start += block) {
    const std::size_t take = std::min(block, samples.size() - start);
    std::copy(samples.begin() + std::ptrdiff_t(start), samples.begin() + std::ptrdiff_t(start + take), fft.real());
    std::fill(fft.real() + take, fft.real() + n, 0.0);
    fft.forward();
    for (std::size_t k = 0; k < bins; ++k) fft.spectrum()[k] *= response[k];
    fft.backward();
    const std::size_t reach = std::min(n, samples.size() - start);
    for (std::size_t i = 0; i < reach; ++i) out[start + i] += fft.real()[i];
  }
  for (std::size_t i = 0; i < samples.size(); ++i) samples[i] = float(out[i]);
}

void apply_room(std::vector<float>& samples, double sample_rate_hz, const Room& room) {
  if (!room.enabled) return;
  convolve_overlap_add(samples, room_impulse_response(room, sample_rate_hz));
}

}  // namespace ms
