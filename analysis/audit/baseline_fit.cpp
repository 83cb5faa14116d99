#include "analysis/audit/baseline_fit.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <sstream>

#include "synthesis/excitation.hpp"

namespace ms::audit {

namespace {

// Weighted least squares of c = a1 + a2 x with weights 1/c^2, a1, a2 >= 0; returns the SSE.
double fit_linear_relative(const std::vector<double>& x, const std::vector<double>& c, double& a1, double& a2) {
  double sw = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double w = 1.0 / (c[i] * c[i]);
    sw += w; sx += w * x[i]; sxx += w * x[i] * x[i]; sy += w * c[i]; sxy += w * x[i] * c[i];
  }
  const double det = sw * sxx - sx * sx;
  a1 = det != 0.0 ? (sxx * sy - sx * sxy) / det : sy / sw;
  a2 = det != 0.0 ? (sw * sxy - sx * sy) / det : 0.0;
  if (a1 < 0.0) { a1 = 0.0; a2 = sxx > 0 ? sxy / sxx : 0.0; }
  if (a2 < 0.0) { a2 = 0.0; a1 = sy / sw; }
  double sse = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) sse += std::pow((c[i] - a1 - a2 * x[i]) / c[i], 2);
  return sse;
}

}  // namespace

DampingLaw fit_law_relative(const std::vector<DampingPoint>& points, DampingKind kind) {
  std::vector<double> lambda, c;
  for (const DampingPoint& p : points) {
    lambda.push_back(p.lambda_rad2_s2);
    c.push_back(std::max(p.c_per_s, 1e-6));
  }
  DampingLaw best;
  best.kind = DampingKind::rayleigh;
  if (points.empty()) return best;
  // Scale lambda so the normal equations are well conditioned.
  const double scale = *std::max_element(lambda.begin(), lambda.end());
  auto fit_at = [&](double a3, DampingLaw& law) {
    std::vector<double> x(lambda.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::pow(lambda[i] / scale, a3);
    double a1 = 0, a2 = 0;
    const double sse = fit_linear_relative(x, c, a1, a2);
    law.alpha1 = a1;
    law.alpha2 = a2 / std::pow(scale, a3);
    law.alpha3 = a3;
    return sse;
  };
  if (kind == DampingKind::rayleigh) {
    fit_at(1.0, best);
    best.alpha3 = 1.0;
    return best;
  }
  best.kind = DampingKind::hybrid;
  double best_sse = 1e300;
  for (int k = 30; k <= 180; ++k) {
    DampingLaw law;
    law.kind = DampingKind::hybrid;
    const double sse = fit_at(0.01 * k, law);
    if (sse < best_sse) { best_sse = sse; best = law; }
  }
  return best;
}

double rms_log_residual(const std::vector<DampingPoint>& points, const std::vector<double>& model_c) {
  double s = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
    s += std::pow(std::log(std::max(model_c[i], 1e-9) / std::max(points[i].c_per_s, 1e-9)), 2);
  return points.empty() ? 0.0 : std::sqrt(s / double(points.size()));
}

DampingLaw trimmed_law(std::vector<DampingPoint> points, DampingKind kind) {
  DampingLaw law = fit_law_relative(points, kind);
  for (int round = 0; round < 2; ++round) {
    std::vector<DampingPoint> near;
    for (const DampingPoint& p : points) {
      const double c = law.decay_per_s(p.lambda_rad2_s2) * 2.0;  // c = 2d
      if (p.c_per_s < 2.5 * c && c < 2.5 * p.c_per_s) near.push_back(p);
    }
    if (near.size() < 3 || near.size() == points.size()) break;
    points = std::move(near);
    law = fit_law_relative(points, kind);
  }
  return law;
}

std::vector<DampingPoint> track_points(const AuditData& data, const std::vector<std::size_t>& strikes,
                                       const std::vector<bool>* only) {
  std::vector<DampingPoint> pts;
  for (std::size_t n = 0; n < data.tracks.size(); ++n) {
    if (only && !(*only)[n]) continue;
    const ModeTrack& t = data.tracks[n];
    for (std::size_t s : strikes)
      if (t.strikes[s].present) pts.push_back(damping_point(t.strikes[s].freq_hz, t.strikes[s].decay_per_s));
  }
  return pts;
}

std::vector<DampingPoint> track_median_points(const AuditData& data, const std::vector<std::size_t>& strikes,
                                              std::vector<std::size_t>* track_index, const std::vector<bool>* only) {
  std::vector<DampingPoint> pts;
  for (std::size_t n = 0; n < data.tracks.size(); ++n) {
    if (only && !(*only)[n]) continue;
    std::vector<double> d;
    for (std::size_t s : strikes)
      if (data.tracks[n].strikes[s].present) d.push_back(data.tracks[n].strikes[s].decay_per_s);
    if (d.empty()) continue;
    std::sort(d.begin(), d.end());
    const double med = d.size() % 2 ? d[d.size() / 2] : 0.5 * (d[d.size() / 2 - 1] + d[d.size() / 2]);
    pts.push_back(damping_point(data.tracks[n].freq_hz, med));
    if (track_index) track_index->push_back(n);
  }
  return pts;
}

std::vector<bool> modelled_tracks(const AuditData& data, const AuditModel& model) {
  std::vector<bool> on(data.tracks.size(), false);
  for (const AuditMode& m : model.modes)
    if (m.track >= 0 && std::size_t(m.track) < on.size()) on[std::size_t(m.track)] = true;
  return on;
}

void apply_law(AuditModel& model) {
  for (AuditMode& m : model.modes) {
    if (m.track < 0) continue;
    const double omega = 2.0 * std::numbers::pi * m.freq_hz;
    m.decay_per_s = std::max(1e-3, model.law.decay_per_s(omega * omega));
  }
}

void fit_amplitudes(AuditModel& model, const AuditData& data, const std::vector<std::size_t>& strikes) {
  // What each strike does to each mode beyond its gain stays while shapes and gains are fitted.
  const std::size_t modes = model.modes.size();
  std::vector<double> factor(strikes.size() * modes, 1.0);
  for (std::size_t k = 0; k < strikes.size(); ++k)
    for (std::size_t n = 0; n < modes; ++n)
      if (model.modes[n].track >= 0) factor[k * modes + n] = strike_factor(model, strikes[k], n);
  for (int round = 0; round < 3; ++round) {
    for (std::size_t n = 0; n < modes; ++n) {
      AuditMode& m = model.modes[n];
      if (m.track < 0) continue;
      double sum = 0.0;
      int count = 0;
      for (std::size_t k = 0; k < strikes.size(); ++k) {
        const std::size_t s = strikes[k];
        const TrackObservation& o = data.tracks[std::size_t(m.track)].strikes[s];
        if (!o.present) continue;
        sum += std::log(o.amp / (model.gain[s] * factor[k * modes + n]));
        ++count;
      }
      if (count > 0) m.amp = std::exp(sum / count);
    }
    for (std::size_t k = 0; k < strikes.size(); ++k)
      fit_gain(model, data, strikes[k], std::span<const double>(factor).subspan(k * modes, modes));
  }
}

void fit_phases(AuditModel& model, const AuditData& data, const std::vector<std::size_t>& strikes) {
  Excitation contact;
  contact.shape = model.contact_shape;
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    AuditMode& m = model.modes[n];
    if (m.track < 0) continue;
    std::complex<double> sum = 0.0;
    for (std::size_t s : strikes) {
      const TrackObservation& o = data.tracks[std::size_t(m.track)].strikes[s];
      if (!o.present || o.members.empty()) continue;
      const Mode& main = *std::max_element(o.members.begin(), o.members.end(),
                                           [](const Mode& a, const Mode& b) { return a.amp < b.amp; });
      double phase = main.phase_rad;
      if (!model.contact_s.empty() && model.contact_s[s] > 0.0) {
        contact.contact_s = model.contact_s[s];
        phase -= std::arg(contact_factor(contact, strike_decay(model, s, n), m.freq_hz));
      }
      sum += main.amp * std::polar(1.0, phase);
    }
    if (std::abs(sum) > 0.0) m.phase_rad = std::arg(sum);
  }
}

AuditModel fit_baseline(const AuditData& data, const std::vector<std::size_t>& strikes_in) {
  const std::vector<std::size_t> strikes = strikes_in.empty() ? all_strikes(data) : strikes_in;
  AuditModel model;
  model.gain.assign(data.strike_count(), 1.0);
  for (std::size_t n = 0; n < data.tracks.size(); ++n) {
    AuditMode m;
    m.freq_hz = data.tracks[n].freq_hz;
    m.track = int(n);
    model.modes.push_back(m);
  }
  model.law = fit_law_relative(track_median_points(data, strikes), DampingKind::rayleigh);  // medians: robust to one odd strike
  apply_law(model);
  fit_amplitudes(model, data, strikes);
  fit_phases(model, data, strikes);
  return model;
}

AuditModel baseline_from_model(const ModalModel& given, const AuditData& data,
                               std::vector<std::size_t>* audit_mode_of_given) {
  AuditModel model;
  model.law_fitted = false;
  model.gain.assign(data.strike_count(), 1.0);
  double matched_energy = 0.0, total_energy = 0.0;
  std::vector<int> mode_of_track(data.tracks.size(), -1);
  const MatchOptions same_track;
  if (audit_mode_of_given) audit_mode_of_given->clear();
  for (const Mode& g : given.modes) {
    double best = 0.01;
    int track = -1;
    for (std::size_t n = 0; n < data.tracks.size(); ++n) {
      const double rel = std::abs(data.tracks[n].freq_hz - g.freq_hz) / g.freq_hz;
      if (rel < best) { best = rel; track = int(n); }
    }
    // Two of the set's modes that one track holds (a plate's split degenerate pair) are one doublet:
    // the track's amplitude is the pair's, not either member's.
    if (track >= 0 && mode_of_track[std::size_t(track)] >= 0) {
      AuditMode& first = model.modes[std::size_t(mode_of_track[std::size_t(track)])];
      const double split_hz = std::abs(g.freq_hz - first.freq_hz);
      if (first.doublet.split_hz == 0.0 &&
          split_hz <= std::max(same_track.merge_hz, same_track.merge_rel * std::min(g.freq_hz, first.freq_hz))) {
        const bool upper = g.freq_hz > first.freq_hz;
        const double lo_amp = upper ? first.amp : std::abs(g.amp), hi_amp = upper ? std::abs(g.amp) : first.amp;
        first.freq_hz = 0.5 * (first.freq_hz + g.freq_hz);
        first.decay_per_s = 0.5 * (first.decay_per_s + g.decay_per_s);
        first.amp = std::hypot(lo_amp, hi_amp);
        first.doublet = {.split_hz = split_hz, .balance = hi_amp / std::max(lo_amp + hi_amp, 1e-300)};
        if (audit_mode_of_given) audit_mode_of_given->push_back(std::size_t(mode_of_track[std::size_t(track)]));
        continue;
      }
      track = -1;  // a track stands for one mode of the set
    }
    AuditMode m;
    m.freq_hz = g.freq_hz;
    m.decay_per_s = g.decay_per_s;
    m.amp = g.amp;
    m.phase_rad = g.phase_rad;
    m.track = track;
    if (track >= 0) mode_of_track[std::size_t(track)] = int(model.modes.size());
    if (audit_mode_of_given) audit_mode_of_given->push_back(model.modes.size());
    model.modes.push_back(m);
  }
  std::vector<bool> used(data.tracks.size(), false);
  for (std::size_t n = 0; n < used.size(); ++n) used[n] = mode_of_track[n] >= 0;
  for (std::size_t n = 0; n < data.tracks.size(); ++n)
    for (const TrackObservation& o : data.tracks[n].strikes) {
      total_energy += o.amp * o.amp;
      if (used[n]) matched_energy += o.amp * o.amp;
    }
  if (total_energy <= 0.0 || matched_energy < 0.5 * total_energy) {
    std::ostringstream msg;
    msg.precision(2);
    msg << "the model's modes do not match the recordings: they account for "
        << std::fixed << 100.0 * (total_energy > 0 ? matched_energy / total_energy : 0.0)
        << " % of the measured modal energy (modes within 1 % in frequency); is it the same object?";
    throw AuditError(msg.str());
  }
  for (std::size_t s = 0; s < data.strike_count(); ++s) fit_gain(model, data, s);
  return model;
}

}  // namespace ms::audit
