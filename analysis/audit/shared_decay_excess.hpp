// Whether the strikes' decays differ by a part each strike's modes share: a hand that grips harder in
// one strike damps all its modes (support_damping), while the extraction's reading of a room's answer
// to each mode wanders from strike to strike mode by mode. A two-way analysis of the log decays
// (mode + strike + residual) over the strong tracks found alone in every strike; the strike term's F
// against the residual and its p-value.
#pragma once
#include <cstddef>

#include "analysis/audit/audit_model.hpp"

namespace ms::audit {

// Tuning seeds: rooms F <= 2.2 over 6-10 strikes (p >= 0.06); the independent generator's hands
// F >= 6.6. The first generator's support draws each mode's excess alone (F 0.5-8.5).
constexpr double kMaxSharedP = 0.01;
// Tracks whose loudest strike lies this far below the strongest track's (-30 dB) have decays too
// noisy to compare across strikes (near the noise); support_damping's spread reads the same tracks.
constexpr double kStrongTrackWithin = 0.0316;
constexpr std::size_t kMinSharedModes = 3;

struct SharedDecayExcess {
  double f = 0.0, p = 1.0;
  std::size_t modes = 0;  // tracks the analysis used (fewer than kMinSharedModes: none shown)
  bool shared() const { return modes >= kMinSharedModes && p < kMaxSharedP; }
};

SharedDecayExcess shared_decay_excess(const AuditData& data);

}  // namespace ms::audit
