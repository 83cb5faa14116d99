// A parameter set as the audit's baseline: its audible modes as they sound after the strike, i.e.
// with the set's strike gain and the contact's per-mode factor |C(d, f)| folded into the amplitudes
// (the audit compares modes, not forces), at the recordings' sample rate.
#pragma once
#include <string>

#include "synthesis/modal_model.hpp"
#include "synthesis/paramset.hpp"

namespace ms::audit {

// Throws AuditError naming `set_path` when the set's sample rate differs from the recordings'.
ModalModel given_model(const ParamSet& set, const std::string& set_path, double recordings_rate_hz);

}  // namespace ms::audit
