#include "analysis/audit/hit_pattern.hpp"

namespace ms::audit {

double HitPattern::log_factor(std::size_t s, std::size_t n) const {
  if (!shape_ln.empty()) {
    if (s >= strike_position.size()) return 0.0;
    const std::vector<double>& at = shape_ln[strike_position[s]];
    return n < at.size() ? at[n] : 0.0;
  }
  if (s >= coord.size() || n >= loading.size()) return 0.0;
  double l = 0.0;
  for (std::size_t k = 0; k < coord[s].size() && k < loading[n].size(); ++k) l += coord[s][k] * loading[n][k];
  return l;
}

}  // namespace ms::audit
