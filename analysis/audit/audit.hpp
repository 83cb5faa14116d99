// The model audit: compare a model with recordings of one object, locate the gap, name
// the missing effects one at a time (detector + cross-validated improvement with a complexity
// penalty), and show the gap before and after. See README "Auditing a model".
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/audit/audit_model.hpp"
#include "analysis/audit/cross_validation.hpp"
#include "analysis/audit/effect_catalog.hpp"
#include "analysis/audit/repeatability_floor.hpp"
#include "analysis/audit/strikes.hpp"

namespace ms::audit {

struct AuditOptions {
  StrikeOptions strikes;
  MatchOptions matching;
  std::size_t max_effects = 3;
  // The given model's mode shapes over hit positions (given_model.hpp's object_shapes): hit_position
  // then fits a position per strike instead of a low-rank pattern. Empty: none known.
  ObjectShapes object_shapes;
};

struct NamedEffect {
  std::string effect;
  double gap_before_db = 0.0, gap_after_db = 0.0;  // in-sample, before and after adding it
  double cv_improvement_db = 0.0;                   // held-out gap improvement (before the penalty)
  Parameters parameters;
  std::string evidence;
  double share_above_floor = 0.0;  // cv_improvement_db / (held-out baseline gap - repeatability floor)
  // Named on its detector's own test where the held-out gap cannot judge it (Detection::held_out_blind),
  // without a held-out improvement beyond its penalty.
  bool named_on_own_test = false;
};

struct Candidate {
  std::string effect;
  bool tested = false;            // false: not enough strikes
  std::string note;               // why not tested / detector evidence
  double statistic = 0.0;
  bool detector_passes = false;
  double cv_gap_db = 0.0;         // held-out gap with the effect (when the detector passed)
  double improvement_db = 0.0;    // held-out improvement minus the penalty
};

// Per-mode residuals of one strike against a model: measured - model (relative freq, relative decay, dB).
struct ModeResidual {
  std::size_t strike = 0;
  double freq_hz = 0.0;
  double freq_rel = 0.0, decay_rel = 0.0, amp_db = 0.0;
};

// Where the gap sits (of the baseline).
struct GapLocation {
  std::vector<double> strike_gap_db;  // per strike
  std::vector<double> band_gap_db;    // per Bark band, over strikes and frames
  std::vector<double> time_gap_db;    // per frame, over strikes and bands
  std::vector<std::size_t> worst_modes;  // indices into the baseline's modes, largest |residual| first (up to 5)
};

struct AuditResult {
  std::string metric;
  std::size_t strikes = 0, modes = 0;
  double gap_before_db = 0.0, gap_after_db = 0.0;
  double cv_gap_before_db = 0.0, cv_gap_after_db = 0.0;
  // The repeatability floor of the final recipe (repeatability_floor.hpp) and the share of the held-out
  // gap above it that the named effects close together ("the gap halves": >= 0.5).
  double floor_db = 0.0;
  std::vector<double> strike_floor_db;
  // Per strike, held out: the final recipe fitted on the other strikes, then adapted to it. The in-sample
  // gap can reach 0 where an effect has a free part per strike (a path through the strikes' own patterns
  // memorises each); this is the gap it reaches on a strike it has not seen.
  std::vector<double> strike_cv_gap_after_db;
  // The baseline's held-out gap per strike; what the strikes still share beyond the final model (not
  // resolved: nothing they share is missing; what varies per strike may still be).
  std::vector<double> strike_cv_gap_before_db;
  SharedResidual left_shared;
  double share_above_floor = 0.0;
  std::vector<NamedEffect> named;
  std::vector<std::vector<Candidate>> rounds;
  std::vector<std::string> untested;  // effects that need more strikes than given, with the reason
  AuditModel baseline, final_model;
  std::vector<GapMap> before, after;  // per strike
  std::vector<ModeResidual> residuals_before, residuals_after;
  GapLocation location;
  std::vector<double> strike_gain_db;  // strike-to-strike variation of the strike strength
  double decay_spread = 0.0;           // median relative spread of a mode's decay across strikes
};

// The measured strikes and their mode tracks (throws AuditError on bad input).
AuditData make_audit_data(const std::vector<Recording>& recordings, const AuditOptions& options = {});

// Runs the audit. `given`: a parameter set's model as the baseline (throws AuditError when its
// modes do not match the recordings).
AuditResult run_audit(const AuditData& data, const std::optional<ModalModel>& given = std::nullopt,
                      const AuditOptions& options = {});

// Per-mode residuals of every strike against a fitted model.
std::vector<ModeResidual> mode_residuals(const AuditData& data, const AuditModel& model);

}  // namespace ms::audit
