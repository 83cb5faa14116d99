// Fit of a decaying white noise (the reverberation extension's additive tail, the residual_transient
// burst): the 60 dB decay time and the energy relative to the direct sound that minimise the mean gap
// over strikes.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/audit/audit_model.hpp"

namespace ms::audit {

// A band a burst may be limited to ([0, 0]: white).
struct NoiseBand {
  double low_hz = 0.0, high_hz = 0.0;
};

struct DecayingNoiseFit {
  double t60_s = 0.0;
  double level_db = 0.0;
  NoiseBand band;  // the best of the bands tried
  double hold_s = 0.0;  // ... and of the holds
  double gap_db = 0.0;  // mean gap over the strikes with this noise added
  double grid_cv_gap_db = 0.0;  // leave-one-strike-out gap of the coarse grid (grid_cross_validation.hpp)
};

// `without` must not contain the noise being fitted. Coarse-to-fine grid search: t60 log-spaced in
// [t60_min_s, t60_max_s], level in [level_min_db, level_max_db]; refine = false stops after the coarse
// grid (6 x 8 points).
// With `bands` and `holds_s`, each band's coarse grid is searched (no hold), then the best band's with
// each hold, and the best refined (the modal rendering is made once for all).
DecayingNoiseFit fit_decaying_noise(const AuditData& data, const AuditModel& without,
                                    const std::vector<std::size_t>& strikes, double t60_min_s, double t60_max_s,
                                    double level_min_db, double level_max_db, bool refine = true,
                                    const std::vector<NoiseBand>& bands = {NoiseBand{}},
                                    const std::vector<double>& holds_s = {0.0});

}  // namespace ms::audit
