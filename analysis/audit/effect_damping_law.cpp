// damping_law: the decays follow a frequency dependence a Rayleigh law (or the given model) cannot
// follow. Detector: a likelihood-ratio-like statistic. Each mode track's median decay is compared with
// the current model and with the best hybrid law c = a1 + a2 omega^(2 a3); the squared log residuals
// are weighted by that median's own uncertainty (strike-to-strike scatter of the track's decays), so
// a deviation counts only where it exceeds what repeated strikes of the same mode disagree by. This
// separates a weak hybrid law (decays precise, systematically off) from support damping (decays
// scattered per strike). Both look only at the tracks the model's modes sit on: those a room's answer
// or a burst's noise made, which the model has dropped, do not decay on the object's law. Beside hand
// damping, where the held-out gap is blind to a law, the decays' lower edge decides (lower_edge_bend.hpp).
// Extension: the hybrid law's decays.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/audit/baseline_fit.hpp"
#include "analysis/audit/effect_catalog.hpp"
#include "analysis/audit/lower_edge_bend.hpp"
#include "analysis/damping/damping_fit.hpp"

namespace ms::audit {

namespace {

// Weighted improvement (sum of squared standardised log residuals, Rayleigh minus hybrid) needed;
// chosen on the tuning seeds (tests/analysis/audit_cases.hpp).
constexpr double kMinChiSquare = 40.0;
constexpr std::size_t kMinTracks = 5;
// A track's log-decay uncertainty never counts as smaller than this: extraction has biases common to
// every strike (a close neighbour, the noise floor) that the strike-to-strike scatter cannot show.
constexpr double kMinLogSe = 0.01;

// Standard error of each track's median log decay: 1.2533 x the robust (MAD) scatter over its
// strikes / sqrt(strikes), floored.
std::vector<double> median_log_se(const AuditData& data, const std::vector<std::size_t>& tracks) {
  std::vector<double> se;
  for (std::size_t t : tracks) {
    std::vector<double> v;
    for (const auto& o : data.tracks[t].strikes)
      if (o.present && o.decay_per_s > 0.0) v.push_back(std::log(o.decay_per_s));
    double s = kMinLogSe;
    if (v.size() >= 3) {
      std::sort(v.begin(), v.end());
      const double med = v[v.size() / 2];
      for (double& x : v) x = std::abs(x - med);
      std::sort(v.begin(), v.end());
      s = std::max(s, 1.2533 * 1.4826 * v[v.size() / 2] / std::sqrt(double(v.size())));
    }
    se.push_back(s);
  }
  return se;
}

double chi_square(const std::vector<DampingPoint>& pts, const std::vector<double>& model_c,
                  const std::vector<double>& se) {
  double s = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    s += std::pow(std::log(std::max(model_c[i], 1e-9) / std::max(pts[i].c_per_s, 1e-9)) / se[i], 2);
  return s;
}

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
  const std::vector<bool> modelled = modelled_tracks(data, current);
  const auto pts = track_median_points(data, all_strikes(data), &tracks, &modelled);
  if (pts.size() < kMinTracks) {
    d.evidence = "too few modes to compare damping laws";
    return d;
  }
  const DampingLaw hybrid = fit_law_relative(pts, DampingKind::hybrid);
  const std::vector<double> cur = current_c(current, tracks), hyb = law_c(hybrid, pts);
  const std::vector<double> se = median_log_se(data, tracks);
  const double before = rms_log_residual(pts, cur);
  const double after = rms_log_residual(pts, hyb);
  d.statistic = chi_square(pts, cur, se) - chi_square(pts, hyb, se);
  d.passes = d.statistic >= kMinChiSquare;
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "the modes' decays deviate from the model's law by %.0f %% RMS, from a hybrid law with "
                "exponent alpha3 = %.2f by %.0f %% (weighted by strike-to-strike scatter: %.0f)",
                100.0 * before, hybrid.alpha3, 100.0 * after, d.statistic);
  d.evidence = buf;
  // Beside hand damping every strike keeps its own decays, so the held-out gap cannot judge a law: the
  // lower edge of their scatter does.
  if (!current.extra_decay_per_s.empty())
    if (const auto bend = lower_edge_bend(data, current); bend && bend->bends()) {
      d.passes = true;
      d.held_out_blind = true;
      std::snprintf(buf, sizeof buf, "; beside the hand's per-strike decays, which leave the held-out gap blind to "
                    "a law, their lower edge bends (hybrid EMG law, alpha3 = %.2f, 2 dlogL = %.1f over Rayleigh)",
                    bend->alpha3, bend->loglik2);
      d.evidence += buf;
    }
  return d;
}

void extend(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train) {
  const std::vector<bool> modelled = modelled_tracks(data, model);
  const auto points = track_points(data, train, &modelled);
  if (!model.extra_decay_per_s.empty() && points.size() >= 8) {
    // With support damping the law is the lower edge of the scatter: refit it as a hybrid EMG.
    model.law = fit_damping(points, DampingKind::hybrid, DampingEstimator::emg).law;
  } else {
    model.law = trimmed_law(track_median_points(data, train, nullptr, &modelled), DampingKind::hybrid);
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
