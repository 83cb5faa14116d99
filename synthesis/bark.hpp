// Bark (critical-band rate) maps: frequency in Hz -> Bark. Used by masking-based mode pruning and
// perceptual distances. Both are monotone increasing for f >= 0 and 0 at 0 Hz.
#pragma once

namespace ms {

// Zwicker & Terhardt (1980): z = 13 atan(0.00076 f) + 3.5 atan((f / 7500)^2).
// E.g. 1000 Hz -> 8.5105 Bark, 16 kHz -> 24.094 Bark.
double bark_zwicker_terhardt(double freq_hz);

// Wang, Sekey & Gersho (1992): z = 6 asinh(f / 600)  (the patent in shared/papers/001 misprints it
// as "6 sin(f/600)"). E.g. 1000 Hz -> 7.7028 Bark.
double bark_wang_sekey_gersho(double freq_hz);

}  // namespace ms
