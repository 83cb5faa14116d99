#include "independent_burst.hpp"

#include <cmath>
#include <numbers>

#include "independent_dsp.hpp"

namespace ms::indep {

std::vector<double> attack_burst(const BurstSpec& burst, double fs, std::mt19937_64& rng) {
  const std::size_t frames = std::size_t(std::lround(burst.duration_s * fs)), settle = 2048;
  std::normal_distribution<double> normal(0.0, 1.0);
  Butterworth4 hp = butterworth4_highpass(burst.low_hz, fs), lp = butterworth4_lowpass(burst.high_hz, fs);
  std::vector<double> y(frames);
  for (std::size_t i = 0; i < settle + frames; ++i) {
    const double v = lp.step(hp.step(normal(rng)));
    if (i >= settle) y[i - settle] = v;
  }
  for (std::size_t i = 0; i < frames; ++i) {
    const double x = double(i) / double(frames);  // 0..1 over the burst
    y[i] *= x < 0.5 ? 1.0 : 0.5 + 0.5 * std::cos(std::numbers::pi * (x - 0.5) / 0.5);
  }
  const double r = rms_of(y, 0, frames);
  if (r > 0.0)
    for (double& v : y) v *= burst.rms / r;
  return y;
}

}  // namespace ms::indep
