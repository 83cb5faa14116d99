#include "synthesis/output_level.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ms {

LevelMode parse_level_mode(const std::string& name) {
  if (const auto mode = find_enum(kLevelModeNames, name)) return *mode;
  throw std::invalid_argument(unknown_name_problem("normalize", name, kLevelModeNames));
}

std::string to_string(LevelMode mode) { return std::string(enum_name(kLevelModeNames, mode)); }

double level_gain(const std::vector<float>& samples, double sample_rate_hz, const OutputLevel& level) {
  const double target = std::pow(10.0, level.target_dbfs / 20.0);
  double measured = 0.0;
  if (level.mode == LevelMode::peak) {
    for (float v : samples) measured = std::max(measured, double(std::abs(v)));
  } else if (level.mode == LevelMode::attack_rms) {
    const std::size_t n = std::min(samples.size(),
                                   std::size_t(std::llround(level.attack_window_s * sample_rate_hz)));
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += double(samples[i]) * samples[i];
    measured = n ? std::sqrt(sum / double(n)) : 0.0;
  } else {
    return 1.0;
  }
  return measured > 0.0 ? target / measured : 1.0;
}

}  // namespace ms
