#include "synthesis/reference_renderer.hpp"

#include <cmath>
#include <complex>
#include <numbers>

namespace ms {

std::vector<double> render_reference(const ModalModel& model, const Excitation& excitation,
                                     double sample_rate_hz, std::size_t frames) {
  std::vector<double> y(frames, 0.0);
  const bool impulse = excitation.shape == PulseShape::impulse || excitation.contact_s <= 0.0;
  for (const Mode& m : model.modes) {
    const double omega = 2.0 * std::numbers::pi * m.freq_hz;
    const std::complex<double> p(-m.decay_per_s, omega);
    const std::complex<double> g = excitation.gain * std::polar(m.amp, m.phase_rad);
    const std::complex<double> after = impulse ? g : g * contact_factor(excitation, m.decay_per_s,
                                                                        m.freq_hz);
    const double amp = std::abs(after), phase = std::arg(after);
    for (std::size_t n = 0; n < frames; ++n) {
      const double t = double(n) / sample_rate_hz;
      if (!impulse && t < excitation.contact_s) {
        y[n] += std::imag(g * std::exp(p * t) * contact_integral(excitation, p, t));
      } else {
        y[n] += amp * std::exp(-m.decay_per_s * t) * std::sin(omega * t + phase);
      }
    }
  }
  return y;
}

}  // namespace ms
