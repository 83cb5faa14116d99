// The audit's baseline: the plain model fitted to the recordings (one mode per track, decays on a
// Rayleigh law, amplitudes = mode shape x strike gain, ideal impulse, free support, no noise, no
// room), or a given parameter set's modes matched to the tracks. Also the relative-error law fit
// both the baseline and the damping_law effect use.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/audit/audit_model.hpp"
#include "analysis/damping/damping_features.hpp"
#include "synthesis/damping_law.hpp"
#include "synthesis/paramset.hpp"

namespace ms::audit {

// Law c(lambda) minimising sum ((c_i - c(lambda_i)) / c_i)^2 (relative errors: low and high modes
// count alike). rayleigh: weighted linear least squares; hybrid: the same for each alpha3 on a grid
// 0.30..1.80 step 0.01, best kept. alpha1, alpha2 >= 0.
DampingLaw fit_law_relative(const std::vector<DampingPoint>& points, DampingKind kind);

// The same, refitted without the points more than 2.5 times off the law (twice): in a room, tracks near a
// mode's frequency decay at the room's rate.
DampingLaw trimmed_law(std::vector<DampingPoint> points, DampingKind kind);

// RMS of log(c_model / c_i) over the points.
double rms_log_residual(const std::vector<DampingPoint>& points, const std::vector<double>& model_c);

// (lambda, c) of every present track observation of the given strikes (of the tracks `only` marks,
// where given).
std::vector<DampingPoint> track_points(const AuditData& data, const std::vector<std::size_t>& strikes,
                                       const std::vector<bool>* only = nullptr);
// One point per track: the median decay over the given strikes.
std::vector<DampingPoint> track_median_points(const AuditData& data, const std::vector<std::size_t>& strikes,
                                              std::vector<std::size_t>* track_index = nullptr,
                                              const std::vector<bool>* only = nullptr);
// The tracks the model's modes sit on (a model may have dropped some: a room's answers, a burst's noise).
std::vector<bool> modelled_tracks(const AuditData& data, const AuditModel& model);

// Amplitude shapes A_n given the strikes' gains (and contacts), then gains again: alternating
// least squares on log amplitudes, three rounds.
void fit_amplitudes(AuditModel& model, const AuditData& data, const std::vector<std::size_t>& strikes);

// Each tracked mode's phase at the onset: the amplitude-weighted circular mean over the strikes of its
// strongest member's measured phase, less the strike's contact phase (when the model has contacts).
void fit_phases(AuditModel& model, const AuditData& data, const std::vector<std::size_t>& strikes);

// Decays of the modes with a track from the model's law.
void apply_law(AuditModel& model);

// The plain model fitted on the given strikes.
AuditModel fit_baseline(const AuditData& data, const std::vector<std::size_t>& strikes);

// A parameter set's modes as the baseline: each mode tied to the nearest track within 1 % (the
// decays and amplitude shapes stay the set's; only the strike gains are fitted); two modes one track
// holds become one doublet mode. audit_mode_of_given (if given) receives each given mode's index in
// the baseline. Throws AuditError when the matched modes carry less than half of the recordings'
// modal energy.
AuditModel baseline_from_model(const ModalModel& given, const AuditData& data,
                               std::vector<std::size_t>* audit_mode_of_given = nullptr);

}  // namespace ms::audit
