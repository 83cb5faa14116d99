// Onset of an impact: the first sample where |x| rises above max(8 sigma, 2 % of the peak), moved
// back while the 8-sample neighbourhood still stands above max(4 sigma, peak - 60 dB), then one sample earlier (the
// last sample at noise level: a struck mode starts from rest, so its first sample is ~0).
#pragma once
#include <cstddef>
#include <vector>

namespace ms {

// sigma: white-noise standard deviation of x (see noise_floor.hpp). Returns x.size() for silence.
std::size_t find_onset(const std::vector<double>& x, double noise_sigma);

}  // namespace ms
