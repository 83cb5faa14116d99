#include "independent_modes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace ms::indep {

std::string shape_name(ForceShape shape) {
  switch (shape) {
    case ForceShape::impulse: return "impulse";
    case ForceShape::hann: return "hann";
    case ForceShape::half_sine: return "half_sine";
    case ForceShape::hertz: return "hertz";
  }
  return "?";
}

double force_shape(ForceShape shape, double x) {
  if (x < 0.0 || x > 1.0) return 0.0;
  const double s = std::sin(std::numbers::pi * x);
  switch (shape) {
    case ForceShape::hann: return 1.0 - std::cos(2.0 * std::numbers::pi * x);
    case ForceShape::half_sine: return s;
    case ForceShape::hertz: return std::pow(std::max(s, 0.0), 1.5);
    case ForceShape::impulse: return 0.0;
  }
  return 0.0;
}

namespace {

using cd = std::complex<double>;

constexpr int kSubSteps = 32;  // Simpson sub-steps per sample (even)

// int_{t0}^{t1} F(u) e^{-s u} du by Simpson's rule (F unnormalised, u in seconds).
cd contact_integral(const Contact& c, cd s, double t0, double t1) {
  if (t1 <= t0) return 0.0;
  const double h = (t1 - t0) / kSubSteps;
  cd sum = 0.0;
  for (int j = 0; j <= kSubSteps; ++j) {
    const double u = t0 + j * h;
    const double w = (j == 0 || j == kSubSteps) ? 1.0 : (j % 2 ? 4.0 : 2.0);
    sum += w * force_shape(c.shape, u / c.duration_s) * std::exp(-s * u);
  }
  return sum * h / 3.0;
}

// int_0^tau F(u) du by Simpson's rule on 4096 steps (the pulses are normalised to unit impulse).
double force_area(const Contact& c) {
  const int n = 4096;
  double a = 0.0;
  for (int j = 0; j <= n; ++j) {
    const double w = (j == 0 || j == n) ? 1.0 : (j % 2 ? 4.0 : 2.0);
    a += w * force_shape(c.shape, double(j) / n);
  }
  return a * c.duration_s / n / 3.0;
}

}  // namespace

std::vector<double> render_modes(const std::vector<DampedMode>& modes, const Contact& contact, double fs,
                                 std::size_t frames) {
  std::vector<double> y(frames, 0.0);
  const bool impulse = contact.shape == ForceShape::impulse || contact.duration_s <= 0.0;
  const double area = impulse ? 1.0 : force_area(contact);
  const std::size_t contact_frames = impulse ? 0 : std::size_t(std::ceil(contact.duration_s * fs));
  for (const DampedMode& m : modes) {
    if (!(m.freq_hz > 0.0 && m.freq_hz < 0.5 * fs)) throw std::invalid_argument("mode frequency outside (0, fs/2)");
    const cd s(-m.decay_per_s, 2.0 * std::numbers::pi * m.freq_hz);
    const cd step = std::exp(s / fs);
    cd z = 1.0;                            // e^{s t}
    cd integral = impulse ? cd(1.0) : 0.0; // int_0^min(t, tau) F(u) e^{-s u} du / area
    for (std::size_t i = 0; i < frames; ++i) {
      if (i % 4096 == 0) z = std::exp(s * (double(i) / fs));
      if (!impulse && i > 0 && i <= contact_frames) {
        const double t0 = double(i - 1) / fs, t1 = std::min(double(i) / fs, contact.duration_s);
        integral += contact_integral(contact, s, t0, t1) / area;
      }
      y[i] += m.amp * (z * integral).imag();
      z *= step;
    }
  }
  return y;
}

}  // namespace ms::indep
