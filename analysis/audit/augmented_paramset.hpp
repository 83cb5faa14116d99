// The audit's improved model as a parameter set (YAML, readable by load_paramset and `modalstudy
// synth`): the fitted modes of one strike (the hardest), with the named effects expressed in the
// existing keys: contact -> excitation raised_cosine, support damping -> effects.support_damping
// per_mode_decay_per_s, doublets -> both modes listed, noise floor -> effects.noise, room ->
// effects.room (the modes then the dry ones it is applied to), an additive tail and an attack burst ->
// effects.reverb and effects.transient. The room's measured answer to each mode (AuditMode::room_answer)
// has no key: effects.room renders its own draw of the room's noise, as a second room of the same RT60s
// and DRR would.
#pragma once
#include <cstddef>
#include <string>

#include "analysis/audit/audit_model.hpp"
#include "synthesis/paramset_recipe.hpp"

namespace ms::audit {

// The strike the parameter set renders: the one with the largest gain.
std::size_t representative_strike(const AuditModel& model);

ParamSetRecipe augmented_recipe(const AuditData& data, const AuditModel& model, const std::string& description);

// write_yaml of augmented_recipe.
std::string augmented_paramset_yaml(const AuditData& data, const AuditModel& model, const std::string& description);

}  // namespace ms::audit
