// |G|, the low-pass a finite contact applies to a mode (synthesis/excitation's contact_factor), as the
// audit's fits need it: about a million times per fit. Closed forms for the raised cosine and the
// half-sine; for Hertz's sin^1.5, which has none, a table over p tau (G depends on p and tau only
// through their product) built once from the quadrature and read bilinearly.
#pragma once
#include "synthesis/excitation.hpp"

namespace ms::audit {

// |G(p)|, p = -decay + i 2 pi freq, for a pulse of `shape` lasting contact_s (1 for contact_s <= 0).
double contact_gain(PulseShape shape, double contact_s, double decay_per_s, double freq_hz);

// The first zero of an undamped mode's |G|: the edge of the pulse's main lobe (2 / tau for the raised
// cosine, 1.5 / tau for the half-sine, 1.7507 / tau for Hertz's pulse; infinity for the impulse).
double first_zero_hz(PulseShape shape, double contact_s);

}  // namespace ms::audit
