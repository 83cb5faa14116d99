// Absolute threshold of hearing (threshold in quiet), Terhardt (1979):
//   T(f) = 3.64 (f/kHz)^-0.8 - 6.5 exp(-0.6 (f/kHz - 3.3)^2) + 1e-3 (f/kHz)^4   [dB SPL].
// E.g. 1 kHz -> 3.369 dB SPL, 50 Hz -> 39.98 dB SPL, minimum -4.98 dB SPL near 3.32 kHz.
#pragma once

namespace ms {

// Defined for freq_hz > 0 (it grows without bound towards 0 Hz).
double threshold_in_quiet_db_spl(double freq_hz);

}  // namespace ms
