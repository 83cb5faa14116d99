#include "analysis/audit/effect_catalog.hpp"

#include <algorithm>

namespace ms::audit {

std::vector<Effect> effect_catalog() {
  return {support_damping_effect(), damping_law_effect(), mode_doublet_effect(), contact_duration_effect(),
          noise_floor_effect(), reverberation_effect(), residual_transient_effect(), hit_position_effect()};
}

const Effect* find_effect(const std::vector<Effect>& catalog, const std::string& name) {
  for (const Effect& e : catalog)
    if (e.name == name) return &e;
  return nullptr;
}

std::vector<std::size_t> strikes_present(const ModeTrack& track) {
  std::vector<std::size_t> s;
  for (std::size_t i = 0; i < track.strikes.size(); ++i)
    if (track.strikes[i].present) s.push_back(i);
  return s;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

Detection detect_by_gap_improvement(const AuditData& data, const AuditModel& current,
                                    void (*extend)(const AuditData&, AuditModel&, const std::vector<std::size_t>&),
                                    double min_improvement_db, const GapEvidence& evidence) {
  AuditModel with = current;
  extend(data, with, all_strikes(data));
  const double before = mean_gap(current, data), after = mean_gap(with, data);
  Detection d;
  d.statistic = before - after;
  d.passes = d.statistic >= min_improvement_db;
  d.evidence = evidence(with, before, after);
  d.extended = std::move(with);
  return d;
}

}  // namespace ms::audit
