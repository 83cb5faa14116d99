#include "synthesis/modal_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ms {

ModalModel at_hit_point(const ModalModel& model, std::size_t index) {
  if (index >= model.hit_gains.size()) throw std::out_of_range("hit point index out of range");
  ModalModel out;
  out.modes = model.modes;
  const auto& g = model.hit_gains[index];
  for (std::size_t n = 0; n < out.modes.size() && n < g.size(); ++n) {
    out.modes[n].amp *= std::abs(g[n]);
    if (g[n] < 0) out.modes[n].phase_rad += std::numbers::pi;  // amp stays >= 0; the sign is a phase
  }
  return out;
}

std::size_t drop_modes_at_or_above(ModalModel& model, double limit_hz) {
  const std::size_t before = model.modes.size();
  std::vector<std::size_t> keep;
  for (std::size_t n = 0; n < before; ++n)
    if (model.modes[n].freq_hz > 0.0 && model.modes[n].freq_hz < limit_hz) keep.push_back(n);
  if (keep.size() == before) return 0;
  ModalModel out;
  for (std::size_t n : keep) out.modes.push_back(model.modes[n]);
  out.hit_point_names = model.hit_point_names;
  for (const auto& row : model.hit_gains) {
    std::vector<double> r;
    for (std::size_t n : keep) r.push_back(n < row.size() ? row[n] : 1.0);
    out.hit_gains.push_back(std::move(r));
  }
  model = std::move(out);
  return before - keep.size();
}

}  // namespace ms
