#include "synthesis/contact_damping.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ms {

std::vector<double> contact_decay_per_s(const std::vector<std::vector<double>>& shapes,
                                        const std::vector<double>& c_per_s, const std::vector<double>& normal_deg,
                                        double mu, std::size_t modes) {
  if (c_per_s.size() != shapes.size() || normal_deg.size() != shapes.size())
    throw std::invalid_argument("contact_decay_per_s: one c and one normal per contact");
  std::vector<double> decay(modes, 0.0);
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    if (shapes[k].size() < modes) throw std::invalid_argument("contact_decay_per_s: a shape per mode at every contact");
    const double cos_theta = std::cos(normal_deg[k] * std::numbers::pi / 180.0);
    const double weight = c_per_s[k] * (mu + (1.0 - mu) * cos_theta * cos_theta);
    for (std::size_t i = 0; i < modes; ++i) decay[i] += 0.5 * weight * shapes[k][i] * shapes[k][i];
  }
  return decay;
}

}  // namespace ms
