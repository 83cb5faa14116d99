#include "analysis/audit/grid_cross_validation.hpp"

#include <cstddef>
#include <limits>

namespace ms::audit {

double leave_one_out_gap(const std::vector<std::vector<double>>& table) {
  if (table.empty() || table.front().empty()) return 0.0;
  const std::size_t strikes = table.front().size();
  std::vector<double> total(table.size(), 0.0);
  for (std::size_t c = 0; c < table.size(); ++c)
    for (double g : table[c]) total[c] += g;
  double held_out = 0.0;
  for (std::size_t k = 0; k < strikes; ++k) {
    std::size_t best = 0;
    double best_rest = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < table.size(); ++c) {
      const double rest = strikes > 1 ? total[c] - table[c][k] : total[c];
      if (rest < best_rest) { best_rest = rest; best = c; }
    }
    held_out += table[best][k];
  }
  return held_out / double(strikes);
}

}  // namespace ms::audit
