// Excitation: the force that strikes the object. An ideal impulse excites every mode with its full
// amplitude; a finite contact of duration tau is a smooth force pulse that low-passes the modes
// (a mode at f >> 1/tau receives little energy). Pulses are normalised to unit momentum (area 1),
// so that tau -> 0 gives the impulse, then multiplied by the strike gain.
#pragma once
#include <complex>
#include <string>

#include "synthesis/name_table.hpp"

namespace ms {

enum class PulseShape { impulse, raised_cosine, hertz, half_sine };
inline constexpr NameTable<PulseShape, 4> kPulseShapeNames{{{PulseShape::impulse, "impulse"},
                                                            {PulseShape::raised_cosine, "raised_cosine"},
                                                            {PulseShape::hertz, "hertz"},
                                                            {PulseShape::half_sine, "half_sine"}}};

struct Excitation {
  PulseShape shape = PulseShape::impulse;
  double contact_s = 0.0;  // duration tau of the force pulse (0 for the impulse)
  double gain = 1.0;       // strike gain (force scale)

  // Force at time t [1/s], area 1 over [0, contact_s]: raised cosine (1 - cos(2 pi t/tau))/tau,
  // Hertz-like sin(pi t/tau)^1.5 / (0.5564... tau) (the half-sine power of Hertzian contact),
  // half-sine (pi/2) sin(pi t/tau)/tau (a linear spring: a stick on a stiff object).
  double force(double t) const;
};

PulseShape parse_pulse_shape(const std::string& name);  // throws std::invalid_argument
std::string to_string(PulseShape shape);

// Complex factor a mode receives once the contact is over, relative to the impulse:
// G(p) = int_0^tau F(s) e^{-p s} ds with p = -d + i omega (mode response Im(a G e^{p t}) for t >= tau).
// |G| is the low-pass the contact applies to that mode.
std::complex<double> contact_factor(const Excitation& e, double decay_per_s, double freq_hz);

// Partial integral int_0^t F(s) e^{-p s} ds for 0 <= t <= tau (composite Gauss-Legendre).
std::complex<double> contact_integral(const Excitation& e, std::complex<double> p, double t);

}  // namespace ms
