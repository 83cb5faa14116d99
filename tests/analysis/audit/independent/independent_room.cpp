#include "independent_room.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "independent_dsp.hpp"

namespace ms::indep {

std::vector<double> room_band(const std::vector<double>& x, std::size_t band, double fs) {
  std::vector<double> y = x;
  if (band > 0) {
    Butterworth4 hp = butterworth4_highpass(kRoomBandEdgesHz[band - 1], fs);
    for (double& v : y) v = hp.step(v);
  }
  if (band < 3) {
    Butterworth4 lp = butterworth4_lowpass(kRoomBandEdgesHz[band], fs);
    for (double& v : y) v = lp.step(v);
  }
  return y;
}

std::vector<double> room_impulse_response(const RoomSpec& room, double fs, std::uint64_t seed) {
  const double longest = *std::max_element(room.rt60_s.begin(), room.rt60_s.end());
  const std::size_t pre = std::size_t(std::lround(room.predelay_s * fs));
  const std::size_t frames = pre + std::size_t(1.5 * longest * fs);
  // The noise starts 4096 samples early so the band filters have settled when the tail begins.
  const std::size_t settle = 4096;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> white(settle + frames);
  for (double& v : white) v = normal(rng);
  std::vector<double> tail(frames, 0.0);
  const double ramp = 1e-3 * fs;  // a 1 ms raised-cosine onset: the diffuse field builds up
  for (std::size_t b = 0; b < 4; ++b) {
    const std::vector<double> band = room_band(white, b, fs);
    const double per_sample = std::log(1000.0) / (room.rt60_s[b] * fs);  // amplitude: -60 dB in RT60
    for (std::size_t i = pre; i < frames; ++i) {
      const double k = double(i - pre);
      const double onset = k < ramp ? 0.5 - 0.5 * std::cos(std::numbers::pi * k / ramp) : 1.0;
      tail[i] += onset * std::exp(-per_sample * k) * band[settle + i];
    }
  }
  double energy = 0.0;
  for (double v : tail) energy += v * v;
  const double scale = std::sqrt(std::pow(10.0, -room.drr_db / 10.0) / energy);
  for (double& v : tail) v *= scale;
  tail[0] += 1.0;  // the direct sound
  return tail;
}

}  // namespace ms::indep
