// Energy-rise onset detector; see onset.hpp.
#include "analysis/extraction/onset.hpp"

#include <algorithm>
#include <cmath>

namespace ms {

std::size_t find_onset(const std::vector<double>& x, double noise_sigma) {
  double peak = 0.0;
  for (double v : x) peak = std::max(peak, std::abs(v));
  if (peak <= 0.0) return x.size();
  const double rise = std::max(8.0 * noise_sigma, 0.02 * peak);
  std::size_t n = 0;
  while (n < x.size() && std::abs(x[n]) < rise) ++n;
  if (n == x.size()) return n;
  // 60 dB under the peak counts as quiet too, should the noise estimate be far too low.
  const double quiet = std::max(4.0 * noise_sigma, 1e-3 * peak);
  constexpr std::size_t kReach = 8;  // a zero crossing of the rising signal must not stop the walk
  auto loud_before = [&](std::size_t at) {
    for (std::size_t i = at >= kReach ? at - kReach : 0; i < at; ++i)
      if (std::abs(x[i]) > quiet) return true;
    return false;
  };
  while (n > 0 && loud_before(n)) --n;
  return n > 0 ? n - 1 : 0;
}

}  // namespace ms
