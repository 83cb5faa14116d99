#include "synthesis/excitation.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ms {

namespace {
// int_0^1 sin(pi x)^1.5 dx = Gamma(1.25) / (sqrt(pi) Gamma(1.75)) = 0.5564178944...
constexpr double kHertzArea = 0.5564178944493822;

// 16-point Gauss-Legendre nodes/weights on [-1, 1] (symmetric halves).
constexpr std::array<double, 8> kGLx = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                                        0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                                        0.9445750230732326, 0.9894009349916499};
constexpr std::array<double, 8> kGLw = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                                        0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                                        0.0622535239386479, 0.0271524594117541};
}  // namespace

double Excitation::force(double t) const {
  if (shape == PulseShape::impulse || contact_s <= 0.0) return 0.0;
  if (t < 0.0 || t > contact_s) return 0.0;
  const double x = t / contact_s;
  if (shape == PulseShape::raised_cosine) return (1.0 - std::cos(2.0 * std::numbers::pi * x)) / contact_s;
  if (shape == PulseShape::half_sine) return 0.5 * std::numbers::pi * std::sin(std::numbers::pi * x) / contact_s;
  return std::pow(std::sin(std::numbers::pi * x), 1.5) / (kHertzArea * contact_s);
}

PulseShape parse_pulse_shape(const std::string& name) {
  if (const auto shape = find_enum(kPulseShapeNames, name)) return *shape;
  throw std::invalid_argument(unknown_name_problem("excitation type", name, kPulseShapeNames));
}

std::string to_string(PulseShape shape) { return std::string(enum_name(kPulseShapeNames, shape)); }

std::complex<double> contact_integral(const Excitation& e, std::complex<double> p, double t) {
  if (e.shape == PulseShape::impulse || e.contact_s <= 0.0) return t >= 0.0 ? 1.0 : 0.0;
  t = std::min(t, e.contact_s);
  if (t <= 0.0) return 0.0;
  // Enough panels that each spans at most a quarter period of the mode.
  const double omega = std::abs(p.imag());
  const int panels = std::max(4, int(std::ceil(t * omega / (std::numbers::pi / 2.0))) + 1);
  const double h = t / panels;
  std::complex<double> sum = 0.0;
  for (int k = 0; k < panels; ++k) {
    const double mid = (k + 0.5) * h;
    for (std::size_t i = 0; i < kGLx.size(); ++i) {
      for (double sign : {-1.0, 1.0}) {
        const double s = mid + sign * kGLx[i] * 0.5 * h;
        sum += kGLw[i] * 0.5 * h * e.force(s) * std::exp(-p * s);
      }
    }
  }
  return sum;
}

std::complex<double> contact_factor(const Excitation& e, double decay_per_s, double freq_hz) {
  const std::complex<double> p(-decay_per_s, 2.0 * std::numbers::pi * freq_hz);
  return contact_integral(e, p, e.contact_s);
}

}  // namespace ms
