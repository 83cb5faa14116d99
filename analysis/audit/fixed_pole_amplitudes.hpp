// A strike's mode amplitudes read again with the poles held fixed. The extraction fits poles and
// amplitudes freely, strike by strike; around a mode in a room it also finds the room's answer as fast
// components, and how it splits them changes from strike to strike once the strikes differ by more than
// a gain, so a few modes are read 5-12 dB off. With the poles fixed the amplitudes are a linear least-
// squares fit (damped_fit.hpp), and the room's answer falls on each mode alike in every strike.
#pragma once
#include <vector>

#include "synthesis/modal_model.hpp"

namespace ms::audit {

// |amplitude| of each of `poles` (their freq_hz and decay_per_s; amp and phase unused) at the first
// sample, fitted jointly from `from_s` on (past the contact) and carried back along each pole's decay.
std::vector<double> fixed_pole_amplitudes(const std::vector<float>& samples, double sample_rate_hz,
                                          const std::vector<Mode>& poles, double from_s);

// Whether two poles split by split_hz, decaying at decay_per_s, drift a radian apart in phase while they
// are heard (for heard_s, or one time constant, whichever is shorter). Closer, their two columns are all
// but one: how a fit of both splits the pair's sound between them is decided by whatever else sounds near
// them (a room's answer, noise), so the pair is read as one pole.
bool pair_beats_apart(double split_hz, double decay_per_s, double heard_s);

}  // namespace ms::audit
