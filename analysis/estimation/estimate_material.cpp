#include "analysis/estimation/estimate_material.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>

#include "analysis/estimation/local_search.hpp"
#include "synthesis/masking_pruning.hpp"

namespace ms {

namespace {

// The modes the masking rule hears, their powers taken after the contact's low-pass (a mode far above
// 1/contact receives almost nothing). |G| > 1 is the e^{d tau} of a mode decaying during the contact
// (up to 1e155 for the fastest), not energy it gains: capped at 1, and a non-finite factor prunes nothing.
ModalModel heard_modes(const ModalModel& model, const Excitation& strike, const PruneOptions& prune) {
  ModalModel struck = model;
  for (Mode& m : struck.modes)
    if (const double g = std::abs(contact_factor(strike, m.decay_per_s, m.freq_hz)); std::isfinite(g))
      m.amp *= std::min(g, 1.0);
  const PruneResult r = prune_modes(struck, prune);
  return progressive_model(model, r, r.kept.size());
}

struct Problem {
  const PerceptualReference& ref;
  const ObjectEigen& object;
  Excitation excitation;
  double sample_rate_hz;
  std::size_t frames;
  const std::optional<PruneOptions>& prune;
  const std::vector<float>& noise;  // added to every candidate (empty: none)

  PerceptualScores score(const Candidate& c, double contact_s) const {
    Excitation strike = excitation;
    strike.contact_s = contact_s;
    ModalModel model = candidate_model(object, c, 0.5 * sample_rate_hz);
    if (prune && !model.modes.empty()) model = heard_modes(model, strike, *prune);
    if (model.modes.empty()) {
      PerceptualScores none;
      none.hybrid = HUGE_VAL;
      return none;
    }
    std::vector<float> y = render_candidate(model, strike, sample_rate_hz, frames);
    for (std::size_t i = 0; i < noise.size() && i < y.size(); ++i) y[i] += noise[i];
    return ref.compare(y, model.modes);
  }
};

// Search coordinates: log alpha, log beta, log gamma, log sigma and, when fitted, log contact.
std::vector<double> to_log(const Candidate& c) {
  return {std::log(c.alpha), std::log(c.beta), std::log(c.gamma), std::log(c.sigma)};
}
Candidate from_log(const std::vector<double>& x) {
  return {std::exp(x[0]), std::exp(x[1]), std::exp(x[2]), std::exp(x[3])};
}

std::size_t matched(const std::vector<FeaturePoint>& reference, const std::vector<Mode>& estimate,
                    const FeatureMatchConstants& constants) {
  std::size_t n = 0;
  for (const FeaturePoint& p : reference) {
    if (!(p.weight > 0)) continue;
    for (const Mode& m : estimate)
      if (point_match_score(feature_distance(p, {m.freq_hz, m.decay_per_s, 1.0}, constants)) > 0) {
        ++n;
        break;
      }
  }
  return n;
}

}  // namespace

MaterialEstimate estimate_material(const std::vector<float>& recording, double sample_rate_hz,
                                   const std::vector<Mode>& modes, const ObjectEigen& object,
                                   const Excitation& excitation, const EstimateOptions& options) {
  const std::size_t frames =
      std::min(recording.size(), std::size_t(std::llround(options.max_duration_s * sample_rate_hz)));
  const std::vector<float> head(recording.begin(), recording.begin() + std::ptrdiff_t(frames));
  const PerceptualReference ref(head, sample_rate_hz, modes, options.perceptual);
  std::vector<double> weights;
  for (const FeaturePoint& p : ref.features()) weights.push_back(p.weight);
  const std::vector<StartPoint> starts =
      start_points(modes, weights, object.lambda0, object.gain, options.dominant_modes, options.start_eigenvalues);
  if (starts.empty()) throw std::invalid_argument("no start point (fewer than two usable modes in the recording)");

  std::optional<PruneOptions> prune;
  if (options.prune_inaudible) {
    prune = PruneOptions{};
    prune->threshold_db = options.prune_threshold_db;
    prune->playback_db = std::min(options.perceptual.playback_db_spl + options.prune_headroom_db, kPlaybackDbMax);
  }
  std::vector<float> noise;
  if (options.noise_sigma > 0) {
    std::mt19937_64 g(0x5eed);
    std::normal_distribution<double> n(0.0, options.noise_sigma);
    noise.resize(frames);
    for (float& v : noise) v = float(n(g));
  }
  const Problem problem{ref, object, excitation, sample_rate_hz, frames, prune, noise};
  const bool fit_contact = options.fit_contact && excitation.shape != PulseShape::impulse;
  const double contact0 =
      std::clamp(excitation.contact_s, options.min_contact_s, options.max_contact_s);
  // Rank the start points by their own metric at the given contact; search from the best few.
  std::vector<std::pair<double, std::size_t>> ranked;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const Candidate c{std::max(starts[i].circle.alpha, 1e-3), std::max(starts[i].circle.beta, 1e-12),
                      starts[i].stiffness_ratio, starts[i].amp_scale};
    ranked.emplace_back(problem.score(c, excitation.contact_s).hybrid, i);
  }
  std::sort(ranked.begin(), ranked.end());
  ranked.resize(std::min(ranked.size(), options.max_starts));

  MaterialEstimate out;
  out.frames = frames;
  out.contact_s = excitation.contact_s;
  double best = HUGE_VAL;
  for (const auto& [value, i] : ranked) {
    StartResult s;
    s.start = starts[i];
    s.initial = {std::max(starts[i].circle.alpha, 1e-3), std::max(starts[i].circle.beta, 1e-12),
                 starts[i].stiffness_ratio, starts[i].amp_scale};
    std::vector<double> x0 = to_log(s.initial);
    BoxedSearchOptions o;
    // alpha and beta over four decades each way, gamma within a factor 1.5, sigma within a factor 10.
    o.lower = {x0[0] - 9.2, x0[1] - 9.2, x0[2] - 0.41, x0[3] - 2.3};
    o.upper = {x0[0] + 9.2, x0[1] + 9.2, x0[2] + 0.41, x0[3] + 2.3};
    o.step = {0.3, 0.3, 0.01, 0.2};
    if (fit_contact) {
      x0.push_back(std::log(contact0));
      o.lower.push_back(std::log(options.min_contact_s));
      o.upper.push_back(std::log(options.max_contact_s));
      o.step.push_back(0.4);
    }
    o.max_evaluations = options.max_evaluations;
    auto contact_of = [&](const std::vector<double>& x) { return fit_contact ? std::exp(x[4]) : excitation.contact_s; };
    const BoxedSearchResult r = nelder_mead_boxed(
        [&](const std::vector<double>& x) { return problem.score(from_log(x), contact_of(x)).hybrid; }, x0, o);
    s.fitted = from_log(r.x);
    s.contact_s = contact_of(r.x);
    s.scores = problem.score(s.fitted, s.contact_s);
    s.iterations = r.iterations;
    s.evaluations = r.evaluations;
    out.iterations += r.iterations;
    if (s.scores.hybrid < best) {
      best = s.scores.hybrid;
      out.material = s.fitted;
      out.contact_s = s.contact_s;
      out.scores = s.scores;
    }
    out.starts.push_back(s);
  }
  out.matched_modes = matched(ref.features(), candidate_model(object, out.material, 0.5 * sample_rate_hz).modes,
                              options.perceptual.match);
  return out;
}

}  // namespace ms
