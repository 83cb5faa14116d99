#include "analysis/audit/lower_edge_bend.hpp"

#include "analysis/audit/baseline_fit.hpp"
#include "analysis/audit/shared_decay_excess.hpp"
#include "analysis/damping/damping_fit.hpp"

namespace ms::audit {

std::optional<LowerEdgeBend> lower_edge_bend(const AuditData& data, const AuditModel& model) {
  if (model.room.enabled || model.reverb.enabled || model.law.kind == DampingKind::hybrid) return std::nullopt;
  const auto pts = track_points(data, all_strikes(data));
  if (pts.size() < 8 || !shared_decay_excess(data).shared()) return std::nullopt;
  const DampingFit straight = fit_damping(pts, DampingKind::rayleigh, DampingEstimator::emg);
  const DampingFit bent = fit_damping(pts, DampingKind::hybrid, DampingEstimator::emg);
  if (!straight.loglik || !bent.loglik) return std::nullopt;
  return LowerEdgeBend{2.0 * (*bent.loglik - *straight.loglik), bent.law.alpha3};
}

}  // namespace ms::audit
