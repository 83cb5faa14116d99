// The independent generator's object response: every mode an exponentially damped sinusoid
// amp e^{-d t} sin(2 pi f t) (a mass-spring-damper's displacement after a unit impulse), summed in
// double precision, struck by a force pulse of finite duration whose convolution with each mode's
// impulse response is integrated numerically.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace ms::indep {

struct DampedMode {
  double freq_hz = 0.0;
  double decay_per_s = 0.0;  // amplitude decay rate d: the envelope is e^{-d t}, T60 = ln(1000) / d
  double amp = 0.0;          // signed: a strike on the other side of a nodal line flips the phase
};

// Contact force shapes on [0, tau], each normalised to unit impulse (area 1): Hann
// (1 - cos 2 pi t/tau), half-sine sin(pi t/tau), Hertz sin^{3/2}(pi t/tau) (a sphere on a flat
// surface); impulse: tau = 0, the ideal strike.
enum class ForceShape { impulse, hann, half_sine, hertz };
std::string shape_name(ForceShape shape);

struct Contact {
  ForceShape shape = ForceShape::impulse;
  double duration_s = 0.0;
};

// The unnormalised force at x = t / tau in [0, 1].
double force_shape(ForceShape shape, double x);

// sum_n (F * h_n)(t) at t = i / sample_rate_hz, i < frames: during the contact each mode's response is
// Im[a e^{s t} int_0^t F(u) e^{-s u} du] with s = -d + i 2 pi f, the integral by Simpson's rule on 32
// sub-steps a sample; after it the mode rings on with the completed integral. e^{s t} by a complex
// recursion re-anchored on the closed form every 4096 samples.
std::vector<double> render_modes(const std::vector<DampedMode>& modes, const Contact& contact, double sample_rate_hz,
                                 std::size_t frames);

}  // namespace ms::indep
