// The double-precision closed form, used as the reference for the resonator bank in tests:
// y(t) = sum_n Im( g_n e^{p_n t} I_n(t) ),  g_n = amp_n e^{i phase_n},  p_n = -d_n + i 2 pi f_n,
// I_n(t) = int_0^min(t,tau) F(s) e^{-p_n s} ds  (I = 1 for the ideal impulse), times the strike gain.
#pragma once
#include <vector>

#include "synthesis/excitation.hpp"
#include "synthesis/modal_model.hpp"

namespace ms {

std::vector<double> render_reference(const ModalModel& model, const Excitation& excitation,
                                     double sample_rate_hz, std::size_t frames);

}  // namespace ms
