// The low-pass anchors of ITU-R BS.1534 (MUSHRA): the reference filtered at 3.5 kHz (and 7 kHz).
// Zero-phase FFT filter with a narrow raised-cosine transition (5 % of the cut-off) so the anchor
// keeps the reference's timing and no ringing of a brick wall is audible.
#pragma once
#include <vector>

namespace ms {

std::vector<float> lowpass_anchor(const std::vector<float>& samples, double sample_rate_hz, double cutoff_hz);

}  // namespace ms
