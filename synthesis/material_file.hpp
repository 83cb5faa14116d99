// Material file: one ms::Material as a small YAML document, so that a material estimated from a
// recording (modalstudy estimate -o) can be used by parameter sets (`material: {file: X.yaml}`).
// The format, units in the key names (c = 2d, lambda = omega^2 in (rad/s)^2, as in damping_law.hpp):
//   id: estimated/spoon                      # required, one line of text
//   source: "modalstudy estimate spoon.wav"  # optional citation / provenance
//   rayleigh: {alpha1_per_s: 2.1364, alpha2_s: 3.0828e-06}             # required: c = alpha1 + alpha2 lambda
//   hybrid: {alpha1_per_s: 39, alpha2: 2.1e-07, alpha3: 0.978}          # optional: c = alpha1 + alpha2 omega^(2 alpha3)
//   specific_modulus_m2_s2: 666250           # required: gamma = E/rho (> 0)
//   modulus_source: "..."                    # optional
//   amp_scale: 3.3276e-06                    # required: Ren's sigma (> 0)
// Numbers are written in their shortest exact form, so writing and reading give the same Material.
#pragma once
#include <string>

#include "synthesis/material.hpp"

namespace ms {

// Reads and checks a material file (at most kYamlFileLimit bytes). Every problem is one InputError
// naming file:line:column: unknown or duplicate keys, missing keys, negative or non-finite values.
Material read_material_file(const std::string& path);
Material parse_material_file(const std::string& yaml_text, const std::string& file_for_errors);

// The file's text for `m` (parse_material_file of it gives back `m`).
std::string material_file_yaml(const Material& m);

}  // namespace ms
