// A parameter set as the audit's baseline: its audible modes as they sound after the strike, i.e.
// with the set's strike gain and the contact's per-mode factor |C(d, f)| folded into the amplitudes
// (the audit compares modes, not forces), at the recordings' sample rate.
#pragma once
#include <string>

#include "analysis/audit/hit_pattern.hpp"
#include "synthesis/modal_model.hpp"
#include "synthesis/paramset.hpp"

namespace ms::audit {

// Throws AuditError naming `set_path` when the set's sample rate differs from the recordings'.
ModalModel given_model(const ParamSet& set, const std::string& set_path, double recordings_rate_hz);

// For a set whose model is an analytic bar or plate (`object:`), the shapes of `given`'s modes over hit
// positions 0.01-0.99 of the length (bar) or 0-0.95 of the radius (plate): each position's set resolved
// and matched to `given` by frequency. Empty for any other set.
ObjectShapes object_shapes(const std::string& set_path, const ModalModel& given, double recordings_rate_hz);

}  // namespace ms::audit
