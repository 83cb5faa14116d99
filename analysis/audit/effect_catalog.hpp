// The catalog of effects an audit can name. Each effect has a detector (a statistic computed on all
// strikes against the current model, with a threshold chosen on the tuning seeds), a model
// extension fitted on training strikes, and the per-strike latent values it estimates on a held-out
// strike (beyond the strike gain every model has).
#pragma once
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/audit/audit_model.hpp"

namespace ms::audit {

struct Detection {
  bool passes = false;
  double statistic = 0.0;
  std::string evidence;   // one sentence
  // Effects whose evidence this one also explains: where this one passes in the same round and
  // improves the held-out gap, it is named before them even if they improve it more.
  std::vector<std::string> precedes;
  // The held-out gap is blind to this effect beside the current model (a law beside hand damping: each
  // held-out strike keeps its own decays), and the detector's own test has decided: it is then named
  // where it costs the held-out gap no more than its penalty.
  bool held_out_blind = false;
  // The current model with this effect extended on every strike, where the detector built it: naming
  // the effect then starts from it (fit_last_effect).
  std::optional<AuditModel> extended;
};

using Parameters = std::vector<std::pair<std::string, double>>;

struct Effect {
  std::string name;
  std::size_t min_strikes = 1;  // fewer strikes: the effect cannot be tested
  double penalty_db = 0.0;      // complexity penalty on the cross-validated gap improvement
  // A catch-all whose free per-strike values could also mimic a specific effect: it is named only in a
  // round where no specific effect's detector passes (the specific explanation goes first).
  bool generic = false;
  Detection (*detect)(const AuditData& data, const AuditModel& current) = nullptr;
  void (*extend)(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train) = nullptr;
  void (*adapt)(const AuditData& data, AuditModel& model, std::size_t strike) = nullptr;  // may be null
  Parameters (*parameters)(const AuditData& data, const AuditModel& model) = nullptr;
  // An effect whose latent values vary from strike to strike may gain held out by what they share: the
  // same extension with no latent values (each strike given what the training strikes share). Where it
  // is set, the effect is named only where its held-out gap is not above this rival's by more than its
  // penalty.
  void (*strike_free_rival)(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train) = nullptr;
};

Effect support_damping_effect();
Effect damping_law_effect();
Effect mode_doublet_effect();
Effect contact_duration_effect();
Effect noise_floor_effect();
Effect reverberation_effect();
Effect residual_transient_effect();
Effect hit_position_effect();

// Every effect, in a fixed order (ties in improvement go to the earlier one).
std::vector<Effect> effect_catalog();
const Effect* find_effect(const std::vector<Effect>& catalog, const std::string& name);

// Strikes that differ by less than this (AuditData::strike_variation_db) differ only in gain.
constexpr double kMinStrikeVariationDb = 0.1;  // tuning seeds: clean 0.00, weakest hidden 0.29 dB

// Helpers the effects share.
std::vector<std::size_t> strikes_present(const ModeTrack& track);
double median(std::vector<double> v);

// A detector whose statistic is the in-sample gap improvement of the effect's extension fitted on all
// strikes: passes at >= min_improvement_db; `evidence(with, before_db, after_db)` writes the sentence.
// The extended model is the detection's `extended` (for a detector that asks more of it).
using GapEvidence = std::function<std::string(const AuditModel& with, double before_db, double after_db)>;
Detection detect_by_gap_improvement(const AuditData& data, const AuditModel& current,
                                    void (*extend)(const AuditData&, AuditModel&, const std::vector<std::size_t>&),
                                    double min_improvement_db, const GapEvidence& evidence);

// White-noise standard deviation with the noise_floor extension's total power (full scale 1).
double noise_white_sigma(const AuditData& data, const AuditModel& model);

}  // namespace ms::audit
