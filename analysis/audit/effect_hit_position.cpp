// hit_position: strikes that move. Where a strike lands sets how strongly each mode sounds (the mode shape
// at the hit point), so the modes' amplitudes change from strike to strike by more than a gain, in a
// pattern the modes share. Detector: on the modes' log-amplitude residuals (measured with the model's
// poles fixed / model), with each strike's gain, smooth spectral tilt and contact mismatch taken out (a
// contact is not a hit point), a pattern fitted on the other strikes predicts half of a held-out strike's
// modes from the other half better than a gain alone, by enough (bi-cross-validation; rank 0 wins on
// independent per-mode scatter, which no model can predict). Extension: with an object's mode shapes (a
// bar or plate parameter set), a hit position per strike; without, a low-rank pattern (loadings per mode
// fitted on the training strikes, rank chosen by the same bi-cross-validation, a weight per strike its
// latent value), or, where it predicts better, a path through the training strikes' own patterns (a strike
// placed on or between two of them: the hit point moves along a line, and shapes that bend between strikes
// are no low rank), or a bending-wave line learnt from the strikes (bending_line.hpp: one coordinate per
// strike places every mode, its shape's wavenumber growing as the square root of its frequency).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>

#include "analysis/audit/baseline_fit.hpp"
#include "analysis/audit/bending_line.hpp"
#include "analysis/audit/contact_spectrum.hpp"
#include "analysis/audit/effect_catalog.hpp"
#include "analysis/audit/fixed_pole_amplitudes.hpp"

namespace ms::audit {

namespace {

constexpr double kWithinDb = 40.0;       // modes this far below the strongest carry the pattern; fainter: noise
constexpr std::size_t kMaxRank = 3;      // patterns beyond three are not hit points but scatter
// Held-out-half RMS improvement over a gain alone, dB. Scatter alone stays under 0.2 dB over every
// strike (the independent generator's true amplitudes without a hit point, and every tuning case
// without one) and 0.21 dB read both ways (its clean held-out cases), so the bar only sets how small a
// pattern may be named; the shuffled-mode null guards against scatter.
constexpr double kMinImprovementDb = 0.3;
constexpr double kDbPerNeper = 8.685889638065035;
// A mode near a node of its shape at some strike's hit point all but vanishes there: its log residual
// would dominate every fit. Residuals are read within -+13 dB.
constexpr double kMaxResidualLn = 1.5;
// The amplitudes are fitted from here on, past a contact (up to 1.5 ms) and its first ringing.
constexpr double kFitFrom_s = 0.002;

// No hit pattern: every strike's modes at the set's amplitudes (the object's grid, if any, stays).
void clear_pattern(HitPattern& hit) {
  if (hit.learnt_line) {
    hit.positions.clear();
    hit.shape_ln.clear();
    hit.learnt_line = false;
  }
  hit.on_path = false;
  hit.loading.clear();
  hit.coord.clear();
  hit.strike_position.clear();
}

// The modes' log-amplitude residuals ln(measured / model without a hit pattern) on the strikes given:
// rows strikes, columns the modes present in all of them and within kWithinDb of the strongest.
struct Residuals {
  std::vector<std::size_t> strikes, modes;
  std::vector<double> freq_hz;  // per column
  Eigen::MatrixXd ln;
};

Residuals residuals(const AuditData& data, const AuditModel& model, const std::vector<std::size_t>& strikes) {
  AuditModel plain = model;
  clear_pattern(plain.hit);
  Residuals r;
  r.strikes = strikes;
  double strongest = 0.0;
  for (const AuditMode& m : model.modes)
    if (m.track >= 0)
      for (std::size_t s : strikes) strongest = std::max(strongest, data.tracks[std::size_t(m.track)].strikes[s].amp);
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    const AuditMode& m = model.modes[n];
    if (m.track < 0 || m.amp <= 0.0) continue;
    bool all = true;
    double loudest = 0.0;
    for (std::size_t s : strikes) {
      const TrackObservation& o = data.tracks[std::size_t(m.track)].strikes[s];
      all &= o.present && o.amp > 0.0;
      loudest = std::max(loudest, o.amp);
    }
    if (all && 20.0 * std::log10(loudest / strongest) >= -kWithinDb) {
      r.modes.push_back(n);
      r.freq_hz.push_back(m.freq_hz);
    }
  }
  // The amplitudes are read again with the model's poles fixed, every tracked mode at once (a doublet's
  // two): the tracks' own, fitted freely, scatter beside a room by as much as a hit pattern moves them
  // (the fit splits the room's answer around a mode differently from strike to strike). A doublet's
  // amplitude is its two modes' added as energies, as its track's is; a pair too close to beat apart while
  // it is heard is read as one pole at its centre (its two members start in phase, so that pole's
  // amplitude is their sum, and the pair's energy that times hypot(1 - balance, balance)).
  r.ln.resize(Eigen::Index(strikes.size()), Eigen::Index(r.modes.size()));
  for (std::size_t i = 0; i < strikes.size(); ++i) {
    // The strike's modes as the model renders them (a doublet as its two) give the poles.
    const ModalModel heard = strike_model(model, strikes[i]);
    const std::vector<float>& samples = data.measured.strikes[strikes[i]].samples;
    const double heard_s = double(samples.size()) / data.measured.sample_rate_hz - kFitFrom_s;
    std::vector<Mode> poles;
    std::vector<std::size_t> first_pole(model.modes.size() + 1, 0);
    std::vector<double> energy_scale(model.modes.size(), 1.0);  // a merged pair's hypot(1 - balance, balance)
    for (std::size_t n = 0, rendered = 0; n < model.modes.size(); ++n) {
      first_pole[n] = poles.size();
      const AuditMode& m = model.modes[n];
      const std::size_t count = rendered_count(m);
      const auto first = heard.modes.begin() + std::ptrdiff_t(rendered);
      rendered += count;
      if (m.track < 0 || m.amp <= 0.0) continue;
      if (count == 2 && !pair_beats_apart(m.doublet.split_hz, first->decay_per_s, heard_s)) {
        Mode centre = *first;
        centre.freq_hz = m.freq_hz;
        poles.push_back(centre);
        energy_scale[n] = std::hypot(1.0 - m.doublet.balance, m.doublet.balance);
      } else {
        poles.insert(poles.end(), first, first + std::ptrdiff_t(count));
      }
    }
    first_pole.back() = poles.size();
    const std::vector<double> amp = fixed_pole_amplitudes(samples, data.measured.sample_rate_hz, poles, kFitFrom_s);
    for (std::size_t j = 0; j < r.modes.size(); ++j) {
      const std::size_t n = r.modes[j];
      double energy = 0.0;
      for (std::size_t k = first_pole[n]; k < first_pole[n + 1]; ++k) energy += amp[k] * amp[k];
      r.ln(Eigen::Index(i), Eigen::Index(j)) = std::clamp(
          std::log(energy_scale[n] * std::sqrt(energy) / strike_amp(plain, strikes[i], n)), -kMaxResidualLn, kMaxResidualLn);
    }
  }
  return r;
}

// Each strike's smooth spectral tilt (1, log f, log^2 f) taken out of its row, and, where the model has a
// contact, what a slightly longer or shorter contact would change to second order (d ln|G| / d ln tau
// and d^2 ln|G| / d (ln tau)^2 at the strike's tau): a contact fitted a little off leaves a pattern that
// is not a hit point, and past a strong contact's first zeros the first order alone does not hold it.
Eigen::MatrixXd without_tilt(const Eigen::MatrixXd& ln, const AuditModel& model, const std::vector<std::size_t>& modes,
                             const std::vector<std::size_t>& strikes) {
  Eigen::MatrixXd out = ln;
  for (Eigen::Index i = 0; i < ln.rows(); ++i) {
    const std::size_t s = strikes[std::size_t(i)];
    const double tau = model.contact_s.empty() ? 0.0 : model.contact_s[s];
    Eigen::MatrixXd basis(ln.cols(), tau > 0.0 ? 5 : 3);
    for (Eigen::Index j = 0; j < ln.cols(); ++j) {
      const std::size_t n = modes[std::size_t(j)];
      const double f = model.modes[n].freq_hz, x = std::log(f / 1000.0);
      basis(j, 0) = 1.0;
      basis(j, 1) = x;
      basis(j, 2) = x * x;
      if (tau > 0.0) {
        const double d = strike_decay(model, s, n);
        const auto g = [&](double t) { return std::log(std::max(contact_gain(model.contact_shape, t, d, f), 1e-6)); };
        basis(j, 3) = (g(1.1 * tau) - g(tau / 1.1)) / (2.0 * std::log(1.1));
        basis(j, 4) = (g(1.1 * tau) - 2.0 * g(tau) + g(tau / 1.1)) / (std::log(1.1) * std::log(1.1));
      }
    }
    const Eigen::MatrixXd projector = basis * basis.completeOrthogonalDecomposition().pseudoInverse();
    out.row(i) = ln.row(i) - ln.row(i) * projector.transpose();
  }
  return out;
}

// Halves of a strike's modes for bi-cross-validation: four different splits (alternate modes, alternate
// pairs, alternate pairs shifted, a fixed scramble), so that no one split's luck decides.
constexpr int kSplits = 4;
bool in_first_half(Eigen::Index j, int split) {
  switch (split) {
    case 0: return j % 2 == 0;
    case 1: return (j / 2) % 2 == 0;
    case 2: return ((j + 1) / 2) % 2 == 0;
    default: return ((j * 2654435761u) >> 7) % 2 == 0;
  }
}

// Rows with each mode's mean over the rows, then each row's own mean, taken out: what a pattern beyond
// the set's amplitudes and each strike's gain must explain.
Eigen::MatrixXd double_centred(const Eigen::MatrixXd& ln) {
  const Eigen::MatrixXd by_mode = ln.rowwise() - ln.colwise().mean();
  return by_mode.colwise() - by_mode.rowwise().mean();
}

// The first `rank` pattern loadings (columns) of rows whose per-mode mean is taken out.
Eigen::MatrixXd loadings(const Eigen::MatrixXd& centred, std::size_t rank) {
  if (rank == 0 || centred.rows() == 0) return Eigen::MatrixXd(centred.cols(), 0);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeThinV);
  return svd.matrixV().leftCols(Eigen::Index(std::min<std::size_t>(rank, std::size_t(svd.matrixV().cols()))));
}

// Gain + weights of the loadings fitted on the modes `fit`, least squares; the fitted coefficients.
Eigen::VectorXd fit_row(const Eigen::VectorXd& x, const Eigen::MatrixXd& load, const std::vector<Eigen::Index>& fit) {
  Eigen::MatrixXd a(Eigen::Index(fit.size()), load.cols() + 1);
  Eigen::VectorXd b(Eigen::Index(fit.size()));
  for (std::size_t i = 0; i < fit.size(); ++i) {
    a(Eigen::Index(i), 0) = 1.0;
    a.row(Eigen::Index(i)).tail(load.cols()) = load.row(fit[i]);
    b(Eigen::Index(i)) = x(fit[i]);
  }
  return a.colPivHouseholderQr().solve(b);
}

// The rows of ln other than row k (the strikes a held-out strike k learns from).
Eigen::MatrixXd without_row(const Eigen::MatrixXd& ln, Eigen::Index k) {
  Eigen::MatrixXd out(ln.rows() - 1, ln.cols());
  for (Eigen::Index s = 0, i = 0; s < ln.rows(); ++s)
    if (s != k) out.row(i++) = ln.row(s);
  return out;
}

// Held-out mean squared errors (natural-log units) pooled over the strikes two ways: over every strike,
// and the median strike's. A strike that landed outside the others' span is predicted by extrapolating
// what was learnt from them; pooled, that one strike decides even where a pattern predicts the others
// many times better, which the median strike shows. Either alone misses hit points the other names.
struct HeldOutMse {
  double pooled = 0.0, median_strike = 0.0;
};

HeldOutMse over_strikes(const std::vector<double>& mse_per_strike) {
  if (mse_per_strike.empty()) return {};
  double sum = 0.0;
  for (double m : mse_per_strike) sum += m;
  return {sum / double(mse_per_strike.size()), median(mse_per_strike)};
}

// Predicting each held-out strike's modes of one half from the other half with a rank-`rank` pattern
// learnt on the other strikes (bi-cross-validation).
HeldOutMse held_out_half_mse(const Eigen::MatrixXd& ln, std::size_t rank) {
  const Eigen::Index strikes = ln.rows(), modes = ln.cols();
  std::vector<double> per_strike;
  for (Eigen::Index k = 0; k < strikes; ++k) {
    double sse = 0.0;
    std::size_t count = 0;
    const Eigen::MatrixXd train = without_row(ln, k);
    const Eigen::RowVectorXd shape = train.colwise().mean();
    const Eigen::MatrixXd load = loadings(double_centred(train), rank);
    const Eigen::VectorXd x = (ln.row(k) - shape).transpose();
    for (int half = 0; half < 2 * kSplits; ++half) {
      std::vector<Eigen::Index> fit, predict;
      for (Eigen::Index j = 0; j < modes; ++j) (in_first_half(j, half / 2) == (half % 2 == 0) ? fit : predict).push_back(j);
      if (fit.size() < std::size_t(load.cols()) + 2 || predict.empty()) continue;
      const Eigen::VectorXd c = fit_row(x, load, fit);
      for (Eigen::Index j : predict) {
        const double e = x(j) - c(0) - load.row(j).dot(c.tail(load.cols()));
        sse += e * e;
        ++count;
      }
    }
    if (count) per_strike.push_back(sse / double(count));
  }
  return over_strikes(per_strike);
}

// The least-squares gain and position (row of `shapes`; none when it has no rows) of a strike's
// residual row x on the modes `fit` (the set's amplitudes stay: no per-mode mean is taken out).
struct Placed {
  Eigen::Index position = -1;
  double gain = 0.0;
};

// Huber loss beyond 8.7 dB: a mode near a node of the shape (or a badly measured faint one) must not
// decide where the strike landed.
double huber(double e) { return std::abs(e) < 1.0 ? e * e : 2.0 * std::abs(e) - 1.0; }

Placed place(const Eigen::VectorXd& x, const Eigen::MatrixXd& shapes, const std::vector<Eigen::Index>& fit) {
  Placed best;
  double best_loss = std::numeric_limits<double>::infinity();
  std::vector<double> d(fit.size());
  for (Eigen::Index p = shapes.rows() > 0 ? 0 : -1; p < shapes.rows(); ++p) {
    for (std::size_t i = 0; i < fit.size(); ++i) d[i] = x(fit[i]) - (p >= 0 ? shapes(p, fit[i]) : 0.0);
    const double gain = median(d);
    double loss = 0.0;
    for (double v : d) loss += huber(v - gain);
    if (loss < best_loss) {
      best_loss = loss;
      best = {p, gain};
    }
    if (p < 0) break;
  }
  return best;
}

// The mean squared error of predicting each half of a strike's modes x from the other half, with the
// strike placed (and its gain chosen) among `shapes` on the first half; no shapes: a gain alone. Appended
// to `per_strike` (nothing where the strike has too few modes).
void add_placed_half_errors(const Eigen::VectorXd& x, const Eigen::MatrixXd& shapes, std::vector<double>& per_strike) {
  double sse = 0.0;
  std::size_t count = 0;
  for (int half = 0; half < 2 * kSplits; ++half) {
    std::vector<Eigen::Index> fit, predict;
    for (Eigen::Index j = 0; j < x.size(); ++j) (in_first_half(j, half / 2) == (half % 2 == 0) ? fit : predict).push_back(j);
    if (fit.size() < 2 || predict.empty()) continue;
    const Placed at = place(x, shapes, fit);
    for (Eigen::Index j : predict) {
      const double e = x(j) - at.gain - (at.position >= 0 ? shapes(at.position, j) : 0.0);
      sse += e * e;
      ++count;
    }
  }
  if (count) per_strike.push_back(sse / double(count));
}

// Hit positions: each strike's position and gain chosen on one half of its modes predict the other
// half (nothing is learnt from the other strikes: the object's shapes are given). No shapes: a gain alone.
HeldOutMse held_out_half_mse_object(const Eigen::MatrixXd& ln, const Eigen::MatrixXd& shapes) {
  std::vector<double> per_strike;
  for (Eigen::Index k = 0; k < ln.rows(); ++k) add_placed_half_errors(ln.row(k).transpose(), shapes, per_strike);
  return over_strikes(per_strike);
}

// The points of a path through `rows` strikes' patterns: each strike's own, and a quarter, half and
// three quarters of the way from each to each other (rows: points, columns: weights summing to 1).
// Where the hit point moves along a line, strikes that land near each other sound alike even where the
// mode shapes bend too much between them for any low-rank pattern (five strikes, upper modes passing
// a node); under independent per-mode scatter a neighbour's pattern carries its own scatter, and a
// gain alone predicts better.
Eigen::MatrixXd path_weights(Eigen::Index rows) {
  constexpr double kSteps[] = {0.25, 0.5, 0.75};
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(rows + 3 * rows * (rows - 1) / 2, rows);
  Eigen::Index p = 0;
  for (Eigen::Index a = 0; a < rows; ++a) w(p++, a) = 1.0;
  for (Eigen::Index a = 0; a < rows; ++a)
    for (Eigen::Index b = a + 1; b < rows; ++b)
      for (double t : kSteps) {
        w(p, a) = 1.0 - t;
        w(p++, b) = t;
      }
  return w;
}

// A held-out strike placed on the path through the other strikes' patterns (bi-cross-validation as above).
HeldOutMse held_out_half_mse_path(const Eigen::MatrixXd& ln) {
  const Eigen::Index strikes = ln.rows();
  const Eigen::MatrixXd weights = path_weights(strikes - 1);
  std::vector<double> per_strike;
  for (Eigen::Index k = 0; k < strikes; ++k) add_placed_half_errors(ln.row(k).transpose(), weights * without_row(ln, k), per_strike);
  return over_strikes(per_strike);
}

// A gain alone, chosen as a strike is placed on a path or a line (median, so a mode near a node does not
// pull it), the training strikes' mean per mode as the shape.
HeldOutMse held_out_half_mse_robust_gain(const Eigen::MatrixXd& ln) {
  std::vector<double> per_strike;
  for (Eigen::Index k = 0; k < ln.rows(); ++k) {
    const Eigen::VectorXd x = (ln.row(k) - without_row(ln, k).colwise().mean()).transpose();
    add_placed_half_errors(x, Eigen::MatrixXd(0, ln.cols()), per_strike);
  }
  return over_strikes(per_strike);
}

// A held-out strike placed on a bending-wave line learnt from the other strikes (bi-cross-validation as above).
HeldOutMse held_out_half_mse_line(const Eigen::MatrixXd& ln, const std::vector<double>& freq_hz) {
  std::vector<double> per_strike;
  for (Eigen::Index k = 0; k < ln.rows(); ++k)
    add_placed_half_errors(ln.row(k).transpose(), fit_bending_line(without_row(ln, k), freq_hz).shapes(), per_strike);
  return over_strikes(per_strike);
}

struct PatternChoice {
  std::size_t rank = 0;  // low-rank patterns
  bool path = false;     // a path through the strikes instead
  bool line = false;     // a bending-wave line instead
  bool median_strike = false;  // the errors compared are the median strike's, not every strike's
  double gain_only_rms = 0.0, pattern_rms = 0.0;  // held-out-half RMS, natural-log units
  bool found() const { return path || line || rank > 0; }
};

// The pattern family that most improves on a gain alone, the held-out errors pooled either way: the
// ranks up to what the strikes and modes allow, the path through the strikes, a bending-wave line
// (none found: a gain alone). Of equal improvements the first family and the pooled errors win.
constexpr Eigen::Index kMinPathStrikes = 4;  // a held-out strike placed among three others at least
PatternChoice choose_pattern(const Eigen::MatrixXd& ln, const std::vector<double>& freq_hz) {
  // A pattern must beat a gain alone however the gain is chosen: least squares (as the ranks fit it) or
  // the median (as the path and the line place a strike, robust to a mode near a node).
  const HeldOutMse least_squares = held_out_half_mse(ln, 0), robust = held_out_half_mse_robust_gain(ln);
  const HeldOutMse gain{std::min(least_squares.pooled, robust.pooled), std::min(least_squares.median_strike, robust.median_strike)};
  struct Family {
    std::size_t rank;
    bool path, line;
    HeldOutMse mse;
  };
  std::vector<Family> families;
  const std::size_t most = std::min({kMaxRank, std::size_t(std::max<Eigen::Index>(ln.rows() - 2, 0)),
                                     std::size_t(std::max<Eigen::Index>(ln.cols() / 2 - 2, 0))});
  for (std::size_t r = 1; r <= most; ++r) families.push_back({r, false, false, held_out_half_mse(ln, r)});
  if (ln.rows() >= kMinPathStrikes) {
    families.push_back({0, true, false, held_out_half_mse_path(ln)});
    families.push_back({0, false, true, held_out_half_mse_line(ln, freq_hz)});
  }
  PatternChoice c;
  c.gain_only_rms = c.pattern_rms = std::sqrt(gain.pooled);
  for (bool by_median : {false, true}) {
    const auto rms = [&](const HeldOutMse& m) { return std::sqrt(by_median ? m.median_strike : m.pooled); };
    const double gain_rms = rms(gain);
    for (const Family& f : families)
      if (gain_rms - rms(f.mse) > c.gain_only_rms - c.pattern_rms) c = {f.rank, f.path, f.line, by_median, gain_rms, rms(f.mse)};
  }
  return c;
}

// What the best pattern gains on the same residuals with every strike's modes shuffled among
// themselves (the largest of kShuffles draws): a pattern shared by the strikes is gone, each strike's
// own scatter stays. A shared pattern must predict better than any of these. The shuffled rows go
// through the detector's own processing (`taken_out`: tilt and contact removed), so that what that
// projection alone leaves predictable (few modes, many terms removed) is in the null too.
constexpr int kShuffles = 39;  // a shared pattern beats all of them: p < 1/40 under independent scatter
double scatter_improvement_db(const Eigen::MatrixXd& ln, const std::vector<double>& freq_hz,
                              const std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>& taken_out) {
  const Eigen::MatrixXd centred = double_centred(ln);
  std::mt19937_64 rng(0x5ca77e4ULL);
  double most = 0.0;
  std::vector<double> row(std::size_t(ln.cols()));
  for (int i = 0; i < kShuffles; ++i) {
    Eigen::MatrixXd shuffled = centred;
    for (Eigen::Index s = 0; s < shuffled.rows(); ++s) {
      for (Eigen::Index j = 0; j < shuffled.cols(); ++j) row[std::size_t(j)] = shuffled(s, j);
      std::shuffle(row.begin(), row.end(), rng);
      for (Eigen::Index j = 0; j < shuffled.cols(); ++j) shuffled(s, j) = row[std::size_t(j)];
    }
    const PatternChoice c = choose_pattern(taken_out(shuffled), freq_hz);
    most = std::max(most, kDbPerNeper * (c.gain_only_rms - c.pattern_rms));
  }
  return most;
}

// The object's shapes on the residual's modes: positions x modes.
Eigen::MatrixXd shapes_on(const AuditModel& model, const std::vector<std::size_t>& modes) {
  Eigen::MatrixXd m(Eigen::Index(model.hit.positions.size()), Eigen::Index(modes.size()));
  for (std::size_t p = 0; p < model.hit.positions.size(); ++p)
    for (std::size_t j = 0; j < modes.size(); ++j) m(Eigen::Index(p), Eigen::Index(j)) = model.hit.shape_ln[p][modes[j]];
  return m;
}

void refit_shapes_and_gains(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train) {
  if (model.law_fitted) fit_amplitudes(model, data, train);
  else for (std::size_t s : train) fit_gain(model, data, s);
}

// A bending-wave line learnt from the training strikes' residuals: its grid and shapes stand in for an
// object's, each training strike at its fitted coordinate, the others at the line's middle until adapted.
void learn_line(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train, const Residuals& r) {
  const BendingLine line = fit_bending_line(r.ln, r.freq_hz);
  const Eigen::MatrixXd shapes = line.shapes();
  HitPattern& hit = model.hit;
  hit.learnt_line = true;
  hit.positions = line_grid_rad();
  hit.home_position = hit.positions.size() / 2;
  hit.shape_ln.assign(hit.positions.size(), std::vector<double>(model.modes.size(), 0.0));
  for (std::size_t p = 0; p < hit.positions.size(); ++p)
    for (std::size_t j = 0; j < r.modes.size(); ++j) hit.shape_ln[p][r.modes[j]] = shapes(Eigen::Index(p), Eigen::Index(j));
  hit.strike_position.assign(data.strike_count(), hit.home_position);
  for (std::size_t i = 0; i < train.size(); ++i) hit.strike_position[train[i]] = line.strike_at[i];
}

constexpr std::size_t kMinModes = 8;  // fewer: no pattern can be told from scatter

void extend(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train) {
  clear_pattern(model.hit);
  const Residuals r = residuals(data, model, train);
  if (r.modes.size() < kMinModes) return;
  if (model.hit.from_object()) {
    const Eigen::MatrixXd shapes = shapes_on(model, r.modes);
    std::vector<Eigen::Index> every(std::size_t(r.ln.cols()));
    for (std::size_t j = 0; j < every.size(); ++j) every[j] = Eigen::Index(j);
    model.hit.strike_position.assign(data.strike_count(), model.hit.home_position);
    for (std::size_t i = 0; i < train.size(); ++i)
      model.hit.strike_position[train[i]] = std::size_t(place(r.ln.row(Eigen::Index(i)).transpose(), shapes, every).position);
  } else {
    const PatternChoice c = choose_pattern(r.ln, r.freq_hz);
    if (!c.found()) return;
    if (c.line) {
      learn_line(data, model, train, r);
      refit_shapes_and_gains(data, model, train);
      return;
    }
    const Eigen::MatrixXd centred = double_centred(r.ln);
    const Eigen::MatrixXd load = c.path ? Eigen::MatrixXd(r.ln.transpose()) : loadings(centred, c.rank);
    model.hit.on_path = c.path;
    model.hit.loading.assign(model.modes.size(), std::vector<double>(std::size_t(load.cols()), 0.0));
    for (std::size_t j = 0; j < r.modes.size(); ++j)
      for (Eigen::Index k = 0; k < load.cols(); ++k) model.hit.loading[r.modes[j]][std::size_t(k)] = load(Eigen::Index(j), k);
    model.hit.coord.assign(data.strike_count(), std::vector<double>(std::size_t(load.cols()), 0.0));
    for (std::size_t i = 0; i < train.size(); ++i) {
      const Eigen::RowVectorXd w =
          c.path ? Eigen::RowVectorXd(Eigen::RowVectorXd::Unit(load.cols(), Eigen::Index(i))) : Eigen::RowVectorXd(centred.row(Eigen::Index(i)) * load);
      model.hit.coord[train[i]].assign(w.data(), w.data() + w.size());
    }
  }
  refit_shapes_and_gains(data, model, train);
}

// A held-out strike: its position (object) or pattern weights, fitted with its gain on its own modes.
void adapt(const AuditData& data, AuditModel& model, std::size_t s) {
  if (!model.hit.active()) return;
  const Residuals r = residuals(data, model, {s});
  if (r.modes.empty()) return;
  const Eigen::VectorXd x = r.ln.row(0).transpose();
  std::vector<Eigen::Index> every(r.modes.size());
  for (std::size_t j = 0; j < every.size(); ++j) every[j] = Eigen::Index(j);
  if (!model.hit.shape_ln.empty()) {  // an object's shapes or a learnt line
    model.hit.strike_position[s] = std::size_t(place(x, shapes_on(model, r.modes), every).position);
    return;
  }
  Eigen::MatrixXd load(Eigen::Index(r.modes.size()), Eigen::Index(model.hit.rank()));
  for (std::size_t j = 0; j < r.modes.size(); ++j)
    for (std::size_t k = 0; k < model.hit.rank(); ++k) load(Eigen::Index(j), Eigen::Index(k)) = model.hit.loading[r.modes[j]][k];
  if (model.hit.on_path) {
    const Eigen::MatrixXd weights = path_weights(load.cols());
    const Eigen::RowVectorXd w = weights.row(place(x, weights * load.transpose(), every).position);
    model.hit.coord[s].assign(w.data(), w.data() + w.size());
    return;
  }
  const Eigen::VectorXd c = fit_row(x, load, every);
  model.hit.coord[s].assign(c.data() + 1, c.data() + c.size());
}

Detection detect(const AuditData& data, const AuditModel& current) {
  Detection d;
  const Residuals r = residuals(data, current, all_strikes(data));
  if (r.modes.size() < kMinModes) {
    d.evidence = "too few modes sound in every strike (" + std::to_string(r.modes.size()) + ") to tell a pattern from scatter";
    return d;
  }
  PatternChoice c;
  if (current.hit.from_object()) {
    // The shapes are given, not learnt from the other strikes: nothing is extrapolated.
    c.gain_only_rms = std::sqrt(held_out_half_mse_object(r.ln, Eigen::MatrixXd(0, r.ln.cols())).pooled);
    c.pattern_rms = std::sqrt(held_out_half_mse_object(r.ln, shapes_on(current, r.modes)).pooled);
    c.rank = c.pattern_rms < c.gain_only_rms ? 1 : 0;
  } else {
    c = choose_pattern(without_tilt(r.ln, current, r.modes, r.strikes), r.freq_hz);
  }
  d.statistic = kDbPerNeper * (c.gain_only_rms - c.pattern_rms);
  const bool beyond_bars = c.found() && d.statistic >= kMinImprovementDb && data.strike_variation_db >= kMinStrikeVariationDb;
  // The shuffles cost forty pattern searches: run only where they decide.
  const bool shuffled = beyond_bars && !current.hit.from_object();
  const double null_db = shuffled ? scatter_improvement_db(r.ln, r.freq_hz, [&](const Eigen::MatrixXd& ln) {
                                      return without_tilt(ln, current, r.modes, r.strikes);
                                    })
                                  : 0.0;
  d.passes = beyond_bars && d.statistic > null_db;
  const std::string shared = current.hit.from_object() ? "in the pattern of the object's mode shapes at a moving hit point"
                             : c.path ? "and strikes that land near each other sound alike (a path through the other strikes' patterns)"
                             : c.line ? "as a hit point moving along a line of bending-wave shapes (wavenumber as the square root of frequency) sets them"
                             : c.rank == 1 ? "in one pattern the strikes share"
                                           : "in " + std::to_string(c.rank) + " patterns the strikes share";
  char null_text[96];
  if (shuffled) std::snprintf(null_text, sizeof null_text, "shuffled modes: at most %.2f dB better", null_db);
  else std::snprintf(null_text, sizeof null_text, "%s", current.hit.from_object() ? "the shapes are given" : "shuffled modes not tried: under the bars");
  char buf[640];
  if (c.found())
    std::snprintf(buf, sizeof buf,
                  "the modes' amplitudes change from strike to strike by more than a gain and a spectral tilt, %s: "
                  "fitted on half of a held-out strike's %zu modes it predicts the other half to %.2f dB RMS instead "
                  "of %.2f dB with a gain alone (%s; %s)",
                  shared.c_str(), r.modes.size(), kDbPerNeper * c.pattern_rms, kDbPerNeper * c.gain_only_rms,
                  c.median_strike ? "the median strike" : "over every strike", null_text);
  else
    std::snprintf(buf, sizeof buf,
                  "%s predicts a held-out strike's modes better than a gain alone (fitted on half of its %zu modes, "
                  "the other half to %.2f dB RMS over every strike)",
                  current.hit.from_object() ? "no hit point on the object's mode shapes" : "no pattern the strikes share",
                  r.modes.size(), kDbPerNeper * c.gain_only_rms);
  d.evidence = buf;
  return d;
}

Parameters parameters(const AuditData& data, const AuditModel& model) {
  double ss = 0.0;
  std::size_t n = 0;
  for (std::size_t s = 0; s < data.strike_count(); ++s)
    for (std::size_t m = 0; m < model.modes.size(); ++m)
      if (model.modes[m].track >= 0) {
        const double l = kDbPerNeper * model.hit.log_factor(s, m);
        ss += l * l;
        ++n;
      }
  Parameters p{{"pattern_rms_db", n ? std::sqrt(ss / double(n)) : 0.0}};
  if (model.hit.from_object()) {
    double lo = 1.0, hi = 0.0;
    for (std::size_t i : model.hit.strike_position) {
      lo = std::min(lo, model.hit.positions[i]);
      hi = std::max(hi, model.hit.positions[i]);
    }
    p.push_back({"position_min", lo});
    p.push_back({"position_max", hi});
  } else if (model.hit.learnt_line) {
    double lo = 1e9, hi = -1e9;
    for (std::size_t i : model.hit.strike_position) {
      lo = std::min(lo, model.hit.positions[i]);
      hi = std::max(hi, model.hit.positions[i]);
    }
    p.push_back({"line_span_rad", hi - lo});
  } else {
    p.push_back({model.hit.on_path ? "path_strikes" : "rank", double(model.hit.rank())});
  }
  return p;
}

}  // namespace

Effect hit_position_effect() {
  return {.name = "hit_position", .min_strikes = 4, .penalty_db = 0.05, .generic = true,
          .detect = detect, .extend = extend, .adapt = adapt, .parameters = parameters};
}

}  // namespace ms::audit
