// damping_law: the decays follow a frequency dependence a Rayleigh law (or the given model) cannot
// follow. Detector: how much better a hybrid law c = a1 + a2 omega^(2 a3) fits the per-mode median
// decays than the current model does (RMS of log residuals). Extension: the hybrid law's decays.
#include <cmath>
#include <cstdio>

#include "analysis/audit/baseline_fit.hpp"
#include "analysis/audit/effect_catalog.hpp"
#include "analysis/damping_fit.hpp"

namespace ms::audit {

namespace {

constexpr double kMinImprovement = 0.05;  // RMS log residual, i.e. ~5 % of every decay (tuning seeds)
constexpr std::size_t kMinTracks = 5;

// Current model's c at each track's median point (the model's own decay of the mode on that track).
std::vector<double> current_c(const AuditModel& model, const std::vector<std::size_t>& tracks) {
  std::vector<double> c;
  for (std::size_t t : tracks) {
    double d = 0.0;
    for (const AuditMode& m : model.modes)
      if (m.track == int(t)) d = m.decay_per_s;
    c.push_back(2.0 * d);
  }
  return c;
}

std::vector<double> law_c(const DampingLaw& law, const std::vector<DampingPoint>& pts) {
  std::vector<double> c;
  for (const DampingPoint& p : pts) c.push_back(2.0 * law.decay_per_s(p.lambda_rad2_s2));
  return c;
}

Detection detect(const AuditData& data, const AuditModel& current) {
  Detection d;
  std::vector<std::size_t> tracks;
  const auto pts = track_median_points(data, all_strikes(data), &tracks);
  if (pts.size() < kMinTracks) {
    d.evidence = "too few modes to compare damping laws";
    return d;
  }
  const DampingLaw hybrid = fit_law_relative(pts, DampingKind::hybrid);
  const double before = rms_log_residual(pts, current_c(current, tracks));
  const double after = rms_log_residual(pts, law_c(hybrid, pts));
  d.statistic = before - after;
  d.passes = d.statistic >= kMinImprovement;
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "the modes' decays deviate from the model's law by %.0f %% RMS, from a hybrid law with "
                "exponent alpha3 = %.2f by %.0f %%",
                100.0 * before, hybrid.alpha3, 100.0 * after);
  d.evidence = buf;
  return d;
}

void extend(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train) {
  const auto points = track_points(data, train);
  if (!model.extra_decay_per_s.empty() && points.size() >= 8) {
    // With support damping the law is the lower edge of the scatter: refit it as a hybrid EMG.
    model.law = fit_damping(points, DampingKind::hybrid, DampingEstimator::emg).law;
  } else {
    model.law = fit_law_relative(track_median_points(data, train), DampingKind::hybrid);
  }
  model.law_fitted = true;
  apply_law(model);
}

Parameters parameters(const AuditData&, const AuditModel& model) {
  return {{"alpha1_per_s", model.law.alpha1}, {"alpha2", model.law.alpha2}, {"alpha3", model.law.alpha3}};
}

}  // namespace

Effect damping_law_effect() {
  return {.name = "damping_law", .min_strikes = 1, .penalty_db = 0.05,
          .detect = detect, .extend = extend, .parameters = parameters};
}

}  // namespace ms::audit
