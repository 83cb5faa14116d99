// Fit of a decaying white noise (the reverberation and residual_transient extensions): the 60 dB
// decay time and the energy relative to the direct sound that minimise the mean gap over strikes.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/audit/audit_model.hpp"

namespace ms::audit {

struct DecayingNoiseFit {
  double t60_s = 0.0;
  double level_db = 0.0;
  double gap_db = 0.0;  // mean gap over the strikes with this noise added
};

// `without` must not contain the noise being fitted. Coarse-to-fine grid search: t60 log-spaced in
// [t60_min_s, t60_max_s], level in [level_min_db, level_max_db].
DecayingNoiseFit fit_decaying_noise(const AuditData& data, const AuditModel& without,
                                    const std::vector<std::size_t>& strikes, double t60_min_s, double t60_max_s,
                                    double level_min_db, double level_max_db);

}  // namespace ms::audit
