#include "analysis/audit/fixed_pole_amplitudes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <numbers>

#include "analysis/extraction/damped_fit.hpp"

namespace ms::audit {

std::vector<double> fixed_pole_amplitudes(const std::vector<float>& samples, double sample_rate_hz,
                                          const std::vector<Mode>& poles, double from_s) {
  const std::size_t from = std::min(samples.size(), std::size_t(std::lround(from_s * sample_rate_hz)));
  const std::vector<double> x(samples.begin() + std::ptrdiff_t(from), samples.end());
  std::vector<DampedComponent> components;
  components.reserve(poles.size());
  for (const Mode& m : poles)
    components.push_back({std::complex<double>(-m.decay_per_s, 2.0 * std::numbers::pi * m.freq_hz) / sample_rate_hz, {}});
  std::vector<double> amp(poles.size(), 0.0);
  if (x.empty() || components.empty()) return amp;
  fit_amplitudes(x, components);
  for (std::size_t k = 0; k < poles.size(); ++k)
    amp[k] = std::abs(components[k].b) * std::exp(poles[k].decay_per_s * double(from) / sample_rate_hz);
  return amp;
}

bool pair_beats_apart(double split_hz, double decay_per_s, double heard_s) {
  const double heard_for_s = decay_per_s > 0.0 ? std::min(heard_s, 1.0 / decay_per_s) : heard_s;
  return 2.0 * std::numbers::pi * split_hz * heard_for_s >= 1.0;
}

}  // namespace ms::audit
