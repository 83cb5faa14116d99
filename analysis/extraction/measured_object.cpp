#include "analysis/extraction/measured_object.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "synthesis/material.hpp"

namespace ms {

ParamSetRecipe measured_object_recipe(const std::vector<Mode>& modes, double sample_rate_hz, double duration_s,
                                      const MeasuredObjectOptions& options) {
  if (modes.empty()) throw std::invalid_argument("no modes to make an object of");
  const Material* material = find_material(options.material);
  if (!material) throw std::invalid_argument("unknown material '" + options.material + "'");
  const double modulus = options.specific_modulus_m2_s2.value_or(material->specific_modulus_m2_s2);
  if (!(modulus > 0.0)) throw std::invalid_argument("the specific modulus must be positive");
  auto power = [](const Mode& m) { return m.amp * m.amp / std::max(m.decay_per_s, 1e-3); };
  double strongest = 0.0;
  for (const Mode& m : modes) strongest = std::max(strongest, power(m));
  const double floor = strongest * std::pow(10.0, -options.range_db / 10.0);
  std::vector<Mode> sorted;
  for (const Mode& m : modes)
    if (power(m) >= floor) sorted.push_back(m);
  std::sort(sorted.begin(), sorted.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  double loudest = 0.0;
  for (const Mode& m : sorted) loudest = std::max(loudest, std::abs(m.amp));
  if (!(loudest > 0.0)) throw std::invalid_argument("every mode has amplitude 0");

  ObjectRecipe object;
  object.type = ObjectType::eigenvalues;
  object.max_modes = std::max<std::size_t>(object.max_modes, sorted.size());
  for (const Mode& m : sorted) {
    // omega^2, not Eq. 12's omega^2 + d^2: a measured decay includes what no damping law holds (the
    // strike's thump reads as a mode decaying at hundreds per second), and it would move the mode
    // wherever the estimated law damps it less; under light damping the two agree.
    const double omega = 2.0 * std::numbers::pi * m.freq_hz;
    object.lambda0.push_back(omega * omega / modulus);
    object.gains.push_back(std::abs(m.amp) / loudest);
  }

  ParamSetRecipe r;
  r.description = options.description;
  r.sample_rate_hz = sample_rate_hz;
  r.duration_s = duration_s;
  r.object = std::move(object);
  r.material = options.material;
  r.specific_modulus_m2_s2 = modulus;
  r.excitation.shape = PulseShape::hertz;
  r.excitation.contact_s = 0.5e-3;  // the extractor's default skip: a real strike's contact
  return r;
}

}  // namespace ms
