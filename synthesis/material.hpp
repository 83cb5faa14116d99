// Material library: published damping parameters (Ren 2013; Sterling et al. 2019), each with its source.
// Eigenvalues are physical (lambda = omega^2, (rad/s)^2). specific_modulus_m2_s2 (gamma = E/rho) sets
// the stiffness of the analytic reference objects; amp_scale is Ren's sigma (1 where unpublished).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "synthesis/damping_law.hpp"

namespace ms {

struct Material {
  std::string id;        // "ren2013/wood", "sterling2019/steel"
  std::string source;    // citation of the damping parameters
  DampingLaw rayleigh;   // always present
  std::optional<DampingLaw> hybrid;  // Sterling's hybrid fit, where published
  double specific_modulus_m2_s2 = 0.0;  // gamma = E/rho
  std::string modulus_source;           // where gamma comes from
  double amp_scale = 1.0;               // Ren's sigma
};

const std::vector<Material>& material_library();

// Lookup by id; nullptr when unknown.
const Material* find_material(const std::string& id);

std::vector<std::string> material_ids();

}  // namespace ms
