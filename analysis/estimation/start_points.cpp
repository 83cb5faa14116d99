// Rayleigh circles through pairs of dominant modes and the starts built on them; see start_points.hpp.
#include "analysis/estimation/start_points.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace ms {

namespace {
double eigenvalue_of(const Mode& m) {
  const double omega = 2.0 * std::numbers::pi * m.freq_hz;
  return omega * omega + m.decay_per_s * m.decay_per_s;
}
}  // namespace

RayleighCircle nearest_physical_circle(const Mode& a, const Mode& b) {
  if (const auto exact = rayleigh_circle_through(a, b)) return *exact;
  const double la = eigenvalue_of(a), lb = eigenvalue_of(b), ca = 2.0 * a.decay_per_s, cb = 2.0 * b.decay_per_s;
  // Least squares of c = alpha + beta lambda through both points with the offending coefficient 0.
  const double beta_only = (ca * la + cb * lb) / (la * la + lb * lb), alpha_only = 0.5 * (ca + cb);
  const double beta_raw = std::abs(la - lb) > 0 ? (ca - cb) / (la - lb) : 0.0;
  if (beta_raw < 0.0) return {alpha_only, 0.0};
  return {0.0, beta_only};
}

std::optional<RayleighCircle> rayleigh_circle_through(const Mode& a, const Mode& b) {
  const double la = eigenvalue_of(a), lb = eigenvalue_of(b);
  if (!(std::abs(la - lb) > 1e-12 * std::max(la, lb))) return std::nullopt;
  RayleighCircle c;
  c.beta = 2.0 * (a.decay_per_s - b.decay_per_s) / (la - lb);
  c.alpha = 2.0 * a.decay_per_s - c.beta * la;
  // A tiny negative alpha from rounding (a law through the origin) is alpha 0.
  if (c.alpha < 0.0 && c.alpha > -1e-9 * std::max(a.decay_per_s, b.decay_per_s)) c.alpha = 0.0;
  if (!(c.beta >= 0.0) || !(c.alpha >= 0.0)) return std::nullopt;
  return c;
}

std::optional<double> eigenvalue_for_frequency(const RayleighCircle& c, double freq_hz) {
  const double omega = 2.0 * std::numbers::pi * freq_hz;
  // (beta^2/4) L^2 + (alpha beta/2 - 1) L + alpha^2/4 + omega^2 = 0; smaller root, written so that it
  // stays accurate as beta -> 0 (then L -> omega^2 + alpha^2/4).
  const double qa = 0.25 * c.beta * c.beta, qb = 0.5 * c.alpha * c.beta - 1.0,
               qc = 0.25 * c.alpha * c.alpha + omega * omega;
  const double disc = qb * qb - 4.0 * qa * qc;
  if (!(disc >= 0.0) || !(qb < 0.0)) return std::nullopt;
  return 2.0 * qc / (-qb + std::sqrt(disc));
}

std::vector<std::size_t> pareto_eigenvalues(const std::vector<double>& lambda0, const std::vector<double>& excitation) {
  if (lambda0.size() != excitation.size()) throw std::invalid_argument("pareto_eigenvalues: sizes differ");
  std::vector<std::size_t> order(lambda0.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return lambda0[i] < lambda0[j]; });
  // Walking up in eigenvalue, a pair survives when its excitation beats every smaller eigenvalue's.
  std::vector<std::size_t> front;
  double best = -1.0;
  for (std::size_t k = 0; k < order.size();) {
    std::size_t end = k;  // equal eigenvalues do not beat each other
    double group_best = best;
    while (end < order.size() && lambda0[order[end]] == lambda0[order[k]]) {
      group_best = std::max(group_best, std::abs(excitation[order[end]]));
      ++end;
    }
    for (std::size_t i = k; i < end; ++i)
      if (std::abs(excitation[order[i]]) >= best && std::abs(excitation[order[i]]) > 0.0) front.push_back(order[i]);
    best = group_best;
    k = end;
  }
  return front;
}

std::vector<StartPoint> start_points(const std::vector<Mode>& modes, const std::vector<double>& weights,
                                     const std::vector<double>& lambda0, const std::vector<double>& excitation,
                                     std::size_t dominant, StartEigenvalues onto) {
  if (weights.size() != modes.size()) throw std::invalid_argument("start_points: one weight per mode");
  if (lambda0.size() != excitation.size()) throw std::invalid_argument("start_points: one excitation per eigenvalue");
  std::vector<std::size_t> rank(modes.size());
  std::iota(rank.begin(), rank.end(), 0);
  std::stable_sort(rank.begin(), rank.end(), [&](std::size_t i, std::size_t j) { return weights[i] > weights[j]; });
  rank.resize(std::min(dominant, rank.size()));
  std::vector<StartPoint> starts;
  if (rank.empty()) return starts;
  const Mode& top = modes[rank.front()];
  std::vector<std::size_t> front;
  if (onto == StartEigenvalues::pareto) {
    front = pareto_eigenvalues(lambda0, excitation);
  } else {
    // The dominant mode is the k-th heard from below; each lower heard mode is a lower eigenvalue
    // (bar spurious ones), missed and doubled (split degenerate) modes push it up, so it is not
    // beyond the 3k + 8 lowest eigenvalues. The cap keeps a plate of hundreds of modes cheap.
    const std::size_t heard_below = std::size_t(
        std::count_if(modes.begin(), modes.end(), [&](const Mode& m) { return m.freq_hz <= top.freq_hz; }));
    std::vector<std::size_t> order(lambda0.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return lambda0[i] < lambda0[j]; });
    for (std::size_t e : order) {
      if (front.size() >= 3 * heard_below + 8) break;
      if (excitation[e] != 0.0 && (front.empty() || lambda0[front.back()] != lambda0[e])) front.push_back(e);
    }
  }
  // The exact circles first; the nearest physical ones only when no exact circle gives a start.
  for (const bool nearest : {false, true}) {
    if (nearest && !starts.empty()) break;
    for (std::size_t p = 0; p < rank.size(); ++p)
      for (std::size_t q = p + 1; q < rank.size(); ++q) {
        const std::optional<RayleighCircle> circle =
            nearest ? std::optional(nearest_physical_circle(modes[rank[p]], modes[rank[q]]))
                    : rayleigh_circle_through(modes[rank[p]], modes[rank[q]]);
        if (!circle) continue;
        const auto lambda = eigenvalue_for_frequency(*circle, top.freq_hz);
        if (!lambda) continue;
        for (std::size_t e : front) {
          if (!(lambda0[e] > 0.0)) continue;
          StartPoint s;
          s.circle = *circle;
          s.stiffness_ratio = *lambda / lambda0[e];
          s.amp_scale = top.amp / std::abs(excitation[e]);
          s.mode_a = rank[p];
          s.mode_b = rank[q];
          s.eigenvalue = e;
          starts.push_back(s);
        }
      }
  }
  return starts;
}

double eigenvalue_alignment(const std::vector<Mode>& modes, const std::vector<double>& weights,
                            const std::vector<double>& lambda0, double gamma, double rel_tol) {
  if (weights.size() != modes.size()) throw std::invalid_argument("eigenvalue_alignment: one weight per mode");
  std::vector<double> sorted(lambda0);
  std::sort(sorted.begin(), sorted.end());
  double lined = 0.0, total = 0.0;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    if (!(weights[i] > 0.0)) continue;
    total += weights[i];
    const double target = eigenvalue_of(modes[i]) / gamma;  // the lambda0 this mode would be
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), target);
    double nearest = HUGE_VAL;
    if (it != sorted.end()) nearest = std::min(nearest, std::abs(*it / target - 1.0));
    if (it != sorted.begin()) nearest = std::min(nearest, std::abs(*std::prev(it) / target - 1.0));
    if (nearest <= rel_tol) lined += weights[i];
  }
  return total > 0.0 ? lined / total : 0.0;
}

}  // namespace ms
