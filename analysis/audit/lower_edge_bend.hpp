// Whether the lower edge of the decays' scatter bends: beside support damping each strike keeps its
// own decays, so a damping law hidden there changes almost no held-out gap, yet the material law the
// hand's excess sits on can still be read. An EMG fit (one-sided excess, Sterling) of every strike's
// (lambda, c) points under a hybrid law against one under a Rayleigh law: twice the log-likelihood
// gain, one degree of freedom more. Read only where a strike's modes share the excess (a hand, not a
// room's answers read mode by mode) and no room is in the model: a room's answers bend the edge too.
#pragma once
#include <optional>

#include "analysis/audit/audit_model.hpp"

namespace ms::audit {

// Chi-square, one degree of freedom, p = 0.001. Tuning pairs hand + law (42556-42571): 4.4-113, 14
// of 16 above; hands alone (42540-42555): at most 3.4.
constexpr double kMinBendLogLik2 = 10.83;

struct LowerEdgeBend {
  double loglik2 = 0.0;  // 2 (log L hybrid - log L Rayleigh)
  double alpha3 = 1.0;   // the hybrid law's exponent
  bool bends() const { return loglik2 >= kMinBendLogLik2; }
};

// Empty where it is not read: too few points, the strikes' modes do not share their excess, a room
// or reverb is in the model, or the model's law is already hybrid.
std::optional<LowerEdgeBend> lower_edge_bend(const AuditData& data, const AuditModel& model);

}  // namespace ms::audit
