#include "analysis/estimation/estimate_material.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/estimation/local_search.hpp"

namespace ms {

namespace {

struct Problem {
  const PerceptualReference& ref;
  const ObjectEigen& object;
  const Excitation& excitation;
  double sample_rate_hz;
  std::size_t frames;

  PerceptualScores score(const Candidate& c) const {
    const ModalModel model = candidate_model(object, c, 0.5 * sample_rate_hz);
    if (model.modes.empty()) {
      PerceptualScores none;
      none.hybrid = HUGE_VAL;
      return none;
    }
    return ref.compare(render_candidate(model, excitation, sample_rate_hz, frames), model.modes);
  }
};

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

  const Problem problem{ref, object, excitation, sample_rate_hz, frames};
  // Rank the start points by their own metric; search from the best few.
  std::vector<std::pair<double, std::size_t>> ranked;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const Candidate c{std::max(starts[i].circle.alpha, 1e-3), std::max(starts[i].circle.beta, 1e-12),
                      starts[i].stiffness_ratio, starts[i].amp_scale};
    ranked.emplace_back(problem.score(c).hybrid, i);
  }
  std::sort(ranked.begin(), ranked.end());
  ranked.resize(std::min(ranked.size(), options.max_starts));

  MaterialEstimate out;
  out.frames = frames;
  double best = HUGE_VAL;
  for (const auto& [value, i] : ranked) {
    StartResult s;
    s.start = starts[i];
    s.initial = {std::max(starts[i].circle.alpha, 1e-3), std::max(starts[i].circle.beta, 1e-12),
                 starts[i].stiffness_ratio, starts[i].amp_scale};
    const std::vector<double> x0 = to_log(s.initial);
    BoxedSearchOptions o;
    // alpha and beta over four decades each way, gamma within a factor 1.5, sigma within a factor 10.
    o.lower = {x0[0] - 9.2, x0[1] - 9.2, x0[2] - 0.41, x0[3] - 2.3};
    o.upper = {x0[0] + 9.2, x0[1] + 9.2, x0[2] + 0.41, x0[3] + 2.3};
    o.step = {0.3, 0.3, 0.01, 0.2};
    o.max_evaluations = options.max_evaluations;
    const BoxedSearchResult r = nelder_mead_boxed(
        [&](const std::vector<double>& x) { return problem.score(from_log(x)).hybrid; }, x0, o);
    s.fitted = from_log(r.x);
    s.scores = problem.score(s.fitted);
    s.iterations = r.iterations;
    s.evaluations = r.evaluations;
    out.iterations += r.iterations;
    if (s.scores.hybrid < best) {
      best = s.scores.hybrid;
      out.material = s.fitted;
      out.scores = s.scores;
    }
    out.starts.push_back(s);
  }
  out.matched_modes = matched(ref.features(), candidate_model(object, out.material, 0.5 * sample_rate_hz).modes,
                              options.perceptual.match);
  return out;
}

}  // namespace ms
