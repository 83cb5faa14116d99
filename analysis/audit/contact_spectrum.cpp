#include "analysis/audit/contact_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <vector>

#include "synthesis/fft.hpp"

namespace ms::audit {

namespace {

// The removable singularities of the closed forms (p = +-i w0) are left to the quadrature.
double by_quadrature(PulseShape shape, double contact_s, double decay_per_s, double freq_hz) {
  Excitation e;
  e.shape = shape;
  e.contact_s = contact_s;
  return std::abs(contact_factor(e, decay_per_s, freq_hz));
}

// G = (1 - e^{-p tau}) w0^2 / (tau p (p^2 + w0^2)), w0 = 2 pi / tau.
double raised_cosine(double tau, std::complex<double> p) {
  const double w0 = 2.0 * std::numbers::pi / tau;
  const std::complex<double> den = tau * p * (p * p + w0 * w0);
  if (std::abs(den) < 1e-12 * w0 * w0 * w0 * tau) return -1.0;
  return std::abs((1.0 - std::exp(-p * tau)) * w0 * w0 / den);
}

// G = (a^2 / 2) (1 + e^{-p tau}) / (p^2 + a^2), a = pi / tau.
double half_sine(double tau, std::complex<double> p) {
  const double a = std::numbers::pi / tau;
  const std::complex<double> den = p * p + a * a;
  if (std::abs(den) < 1e-12 * a * a) return -1.0;
  return std::abs(0.5 * a * a * (1.0 + std::exp(-p * tau)) / den);
}

// Hertz: |G| on x = omega tau in [0, kMaxX] and y = decay tau in [0, kMaxY], at tau = 1: for each y
// the pulse times e^{y u} sampled at kSamples midpoints and transformed by one zero-padded FFT, whose
// bin j is x = 2 pi j kSamples / kFftSize (the midpoints' half-sample shift changes only the phase).
// Past kMaxX (more than 50 periods inside the contact) the side lobes are below -90 dB: read the
// edge; past kMaxY the mode decays by more than e within the contact, which no struck mode does.
constexpr std::size_t kSamples = 2048, kFftSize = std::size_t(1) << 19;
constexpr double kStepX = 2.0 * std::numbers::pi * double(kSamples) / double(kFftSize);  // 0.0245
constexpr double kMaxX = 320.0, kMaxY = 1.0, kStepY = 0.1;
constexpr std::size_t kNx = std::size_t(kMaxX / kStepX) + 2, kNy = std::size_t(kMaxY / kStepY + 0.5) + 1;

const std::vector<double>& hertz_table() {
  static const std::vector<double> table = [] {
    std::vector<double> t(kNx * kNy);
    Excitation e;
    e.shape = PulseShape::hertz;
    e.contact_s = 1.0;
    RealFft fft(kFftSize);
    for (std::size_t j = 0; j < kNy; ++j) {
      const double y = double(j) * kStepY;
      std::fill(fft.real(), fft.real() + kFftSize, 0.0);
      for (std::size_t k = 0; k < kSamples; ++k) {
        const double u = (double(k) + 0.5) / double(kSamples);
        fft.real()[k] = e.force(u) * std::exp(y * u) / double(kSamples);
      }
      fft.forward();
      for (std::size_t i = 0; i < kNx; ++i) t[j * kNx + i] = std::abs(fft.spectrum()[i]);
    }
    return t;
  }();
  return table;
}

double hertz(double tau, double decay_per_s, double freq_hz) {
  const std::vector<double>& t = hertz_table();
  const double x = std::min(2.0 * std::numbers::pi * freq_hz * tau, kMaxX) / kStepX;
  const double y = std::clamp(decay_per_s * tau, 0.0, kMaxY) / kStepY;
  const std::size_t i = std::min(std::size_t(x), kNx - 2), j = std::min(std::size_t(y), kNy - 2);
  const double fx = x - double(i), fy = y - double(j);
  const auto at = [&](std::size_t jj, std::size_t ii) { return t[jj * kNx + ii]; };
  return (1 - fy) * ((1 - fx) * at(j, i) + fx * at(j, i + 1)) + fy * ((1 - fx) * at(j + 1, i) + fx * at(j + 1, i + 1));
}

}  // namespace

double first_zero_hz(PulseShape shape, double contact_s) {
  if (contact_s <= 0.0) return std::numeric_limits<double>::infinity();
  switch (shape) {
    case PulseShape::raised_cosine: return 2.0 / contact_s;
    case PulseShape::half_sine: return 1.5 / contact_s;
    case PulseShape::hertz: return 1.7507 / contact_s;
    case PulseShape::impulse: break;
  }
  return std::numeric_limits<double>::infinity();
}

double contact_gain(PulseShape shape, double contact_s, double decay_per_s, double freq_hz) {
  if (contact_s <= 0.0 || shape == PulseShape::impulse) return 1.0;
  const std::complex<double> p(-decay_per_s, 2.0 * std::numbers::pi * freq_hz);
  double g = -1.0;
  switch (shape) {
    case PulseShape::raised_cosine: g = raised_cosine(contact_s, p); break;
    case PulseShape::half_sine: g = half_sine(contact_s, p); break;
    case PulseShape::hertz: return hertz(contact_s, decay_per_s, freq_hz);
    case PulseShape::impulse: return 1.0;
  }
  return g >= 0.0 ? g : by_quadrature(shape, contact_s, decay_per_s, freq_hz);
}

}  // namespace ms::audit
