// The --law option of `fit-damping` and `plot damping`: a damping law that can be fitted to features
// (constant_q is a law but not a fittable one), refused by the option's name otherwise.
#pragma once
#include <stdexcept>
#include <string>

#include "analysis/damping/emg_likelihood.hpp"
#include "synthesis/damping_law.hpp"
#include "synthesis/input_error.hpp"

namespace ms::cli {

inline DampingKind parse_fittable_law(const std::string& name) {
  try {
    const DampingKind law = parse_damping_kind(name);
    law_param_count(law);  // throws for constant_q
    return law;
  } catch (const std::invalid_argument&) {
    throw InputError(SourceLocation{"--law", 0, 0}, "unknown law '" + name + "' (expected rayleigh, powerlaw or hybrid)");
  }
}

}  // namespace ms::cli
