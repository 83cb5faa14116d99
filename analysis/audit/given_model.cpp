// A parameter set's modes as the audit's baseline; see given_model.hpp.
#include "analysis/audit/given_model.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "analysis/audit/strikes.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/paramset_recipe.hpp"
#include "synthesis/stimulus.hpp"

namespace ms::audit {

ModalModel given_model(const ParamSet& set, const std::string& set_path, double recordings_rate_hz) {
  if (set.sample_rate_hz != recordings_rate_hz)
    throw AuditError(set_path + ": sample rate " + std::to_string(std::lround(set.sample_rate_hz)) +
                     " Hz differs from the recordings' " + std::to_string(std::lround(recordings_rate_hz)) + " Hz");
  std::vector<std::string> warnings;
  ModalModel model = audible_model(set, warnings);
  for (Mode& m : model.modes) {
    const std::complex<double> c = contact_factor(set.excitation, m.decay_per_s, m.freq_hz);
    m.amp *= set.excitation.gain * std::abs(c);
    m.phase_rad += std::arg(c);
  }
  return model;
}

namespace {

// A node gives no sound at all; the shapes stay within +-40 dB of the set's own hit.
constexpr double kMaxShapeRatio = 100.0;

// The set's own hit on the object: its named point or its default, as a fraction.
double home_of(const ParamSetRecipe& recipe) {
  const ObjectRecipe& o = *recipe.object;
  for (const HitPoint& h : o.hit_points)
    if (h.name == recipe.hit) return h.position;
  return o.type == ObjectType::bar ? o.hit_position : o.hit_radius;
}

}  // namespace

ObjectShapes object_shapes(const std::string& set_path, const ModalModel& given, double recordings_rate_hz) {
  ObjectShapes shapes;
  const ParamSetRecipe recipe = read_recipe_file(set_path);
  if (!recipe.object || recipe.object->type == ObjectType::eigenvalues) return shapes;
  const bool bar = recipe.object->type == ObjectType::bar;
  const double home = home_of(recipe);
  for (int i = bar ? 1 : 0; i <= (bar ? 99 : 95); ++i) shapes.positions.push_back(0.01 * i);
  shapes.positions.push_back(home);
  std::sort(shapes.positions.begin(), shapes.positions.end());
  shapes.positions.erase(std::unique(shapes.positions.begin(), shapes.positions.end(),
                                     [](double a, double b) { return std::abs(a - b) < 1e-12; }),
                         shapes.positions.end());
  for (double x : shapes.positions) {
    if (std::abs(x - home) < 1e-12) {
      shapes.home_position = shapes.shape_ln.size();
      shapes.shape_ln.emplace_back(given.modes.size(), 0.0);
      continue;
    }
    ParamSetRecipe at = recipe;
    at.hit.clear();
    (bar ? at.object->hit_position : at.object->hit_radius) = x;
    at.prune.reset();
    const ModalModel there = given_model(resolve(at), set_path, recordings_rate_hz);
    std::vector<double> row;
    for (const Mode& g : given.modes) {
      double ratio = 1.0;
      for (const Mode& m : there.modes)
        if (std::abs(m.freq_hz - g.freq_hz) <= 1e-6 * g.freq_hz) {
          ratio = std::abs(m.amp) / std::max(std::abs(g.amp), 1e-300);
          break;
        }
      row.push_back(std::log(std::clamp(ratio, 1.0 / kMaxShapeRatio, kMaxShapeRatio)));
    }
    shapes.shape_ln.push_back(std::move(row));
  }
  return shapes;
}

}  // namespace ms::audit
