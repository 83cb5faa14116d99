// An object made from one recording's modes: the stand-in for a modal analysis a modeller does not
// have. Its eigenvalues are the measured modes' omega^2 / (E/rho) for the stiffness the
// stand-in assumes (by default its material's), and its gains the measured amplitudes (the loudest 1),
// so the set renders the recording's frequencies with its material's damping, and material estimation
// fits the damping, the amplitude scale and a stiffness near the one assumed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "synthesis/modal_model.hpp"
#include "synthesis/paramset_recipe.hpp"

namespace ms {

struct MeasuredObjectOptions {
  std::string material = "ren2013/metal";  // the damping the set renders with until one is estimated
  std::optional<double> specific_modulus_m2_s2;  // E/rho the eigenvalues are written for (the material's)
  // Modes whose power A^2/d is this far under the strongest's are left out: weak readings of noise,
  // room and attack that a modal analysis of the object would not list.
  double range_db = 40.0;
  std::string description;
};

// A parameter set with an `eigenvalues` object of the modes within range (sorted by frequency). Throws
// std::invalid_argument for no modes, an unknown material or a non-positive modulus.
ParamSetRecipe measured_object_recipe(const std::vector<Mode>& modes, double sample_rate_hz, double duration_s,
                                      const MeasuredObjectOptions& options);

}  // namespace ms
