#include "analysis/estimation/estimate_material.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <random>
#include <stdexcept>

#include "analysis/estimation/iso226_loudness.hpp"
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
  double floor_amp;                 // render_candidate_above's floor
  double noise_sigma;               // added by its expected power (0: none, or the draw in `noise`)

  PerceptualScores score(const Candidate& c, double contact_s) const {
    Excitation strike = excitation;
    strike.contact_s = contact_s;
    ModalModel model = candidate_model(object, c, 0.5 * sample_rate_hz);
    if (model.modes.empty()) {
      PerceptualScores none;
      none.hybrid = HUGE_VAL;
      return none;
    }
    // Pruning changes what is rendered, not the candidate's feature points: a masked mode is still a
    // mode of the material, and leaving it out of the match moves the feature metric.
    std::vector<float> y = render_candidate_above(prune ? heard_modes(model, strike, *prune) : model, strike,
                                                  sample_rate_hz, frames, floor_amp);
    if (noise_sigma > 0.0) return ref.compare(y, model.modes, noise_sigma);
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

Candidate initial_candidate(const StartPoint& p) {
  return {std::max(p.circle.alpha, 1e-3), std::max(p.circle.beta, 1e-12), p.stiffness_ratio, p.amp_scale};
}

// The starts searched, best first. Each gamma candidate (an eigenvalue the dominant mode is mapped
// onto) is judged by how many of the recording's modes it lines up with eigenvalues
// (eigenvalue_alignment): the max_starts best-aligned are kept. Of each one's start points (one per
// circle) the imaged_per_gamma best by the feature metric alone (no render) are scored by the whole
// metric at the given contact, and the best of them is the gamma's start.
std::vector<std::size_t> choose_starts(const std::vector<StartPoint>& starts, const Problem& problem, double contact_s,
                                       const std::vector<Mode>& modes, const std::vector<double>& weights,
                                       const EstimateOptions& options) {
  std::vector<std::size_t> gammas;  // eigenvalue indices, in order of first appearance
  std::vector<double> alignment;
  for (const StartPoint& s : starts)
    if (std::find(gammas.begin(), gammas.end(), s.eigenvalue) == gammas.end()) {
      gammas.push_back(s.eigenvalue);
      alignment.push_back(eigenvalue_alignment(modes, weights, problem.object.lambda0, s.stiffness_ratio));
    }
  std::vector<std::size_t> order(gammas.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) { return alignment[p] > alignment[q]; });
  order.resize(std::min(order.size(), options.max_starts));
  std::vector<std::size_t> chosen;
  for (const std::size_t g : order) {
    std::vector<std::pair<double, std::size_t>> ranked;
    for (std::size_t i = 0; i < starts.size(); ++i) {
      if (starts[i].eigenvalue != gammas[g]) continue;
      const ModalModel model =
          candidate_model(problem.object, initial_candidate(starts[i]), 0.5 * problem.sample_rate_hz);
      const std::vector<FeaturePoint> points = loudness_weighted_features(
          model.modes, problem.ref.imager(), problem.ref.db_spl_at_unit_power(), problem.ref.sone().frames);
      ranked.emplace_back(match_ratio_product(problem.ref.features(), points, options.perceptual.match).product, i);
    }
    std::stable_sort(ranked.begin(), ranked.end());
    ranked.resize(std::min(ranked.size(), std::max<std::size_t>(options.imaged_per_gamma, 1)));
    for (auto& [value, i] : ranked) value = problem.score(initial_candidate(starts[i]), contact_s).hybrid;
    chosen.push_back(std::min_element(ranked.begin(), ranked.end())->second);
  }
  return chosen;
}

// What every candidate is compared with: the recording's head, its reference, the pruning rule and
// the noise added to each candidate.
struct Setup {
  std::size_t frames;
  PerceptualReference ref;
  std::optional<PruneOptions> prune;
  std::vector<float> noise;
  double floor_amp = 0.0;
  double noise_sigma = 0.0;
  Setup(const std::vector<float>& recording, double sample_rate_hz, const std::vector<Mode>& modes,
        const EstimateOptions& options)
      : frames(std::min(recording.size(), std::size_t(std::llround(options.max_duration_s * sample_rate_hz)))),
        ref(std::vector<float>(recording.begin(), recording.begin() + std::ptrdiff_t(frames)), sample_rate_hz, modes,
            options.perceptual) {
    if (options.prune_inaudible) {
      prune = PruneOptions{};
      prune->threshold_db = options.prune_threshold_db;
      prune->playback_db = std::min(options.perceptual.playback_db_spl + options.prune_headroom_db, kPlaybackDbMax);
    }
    if (options.render_floor_below_quiet_db >= 0.0) {
      double quiet_db = HUGE_VAL;
      for (const Iso226Row& row : iso226_table()) quiet_db = std::min(quiet_db, row.tf_db);
      // A sine of amplitude A has mean square A^2/2, heard at 10 log10(A^2/2) + calibration dB SPL.
      const double quiet_mean_square =
          std::pow(10.0, (quiet_db - options.render_floor_below_quiet_db - ref.db_spl_at_unit_power()) / 10.0);
      floor_amp = std::sqrt(2.0 * quiet_mean_square);
      if (options.noise_sigma > 0 && options.render_floor_below_noise_db >= 0.0)
        floor_amp =
            std::max(floor_amp, options.noise_sigma * std::pow(10.0, -options.render_floor_below_noise_db / 20.0));
    }
    if (options.noise_sigma > 0 && options.noise_by_expected_power) noise_sigma = options.noise_sigma;
    if (options.noise_sigma > 0 && !options.noise_by_expected_power) {
      std::mt19937_64 g(0x5eed);
      std::normal_distribution<double> n(0.0, options.noise_sigma);
      noise.resize(frames);
      for (float& v : noise) v = float(n(g));
    }
  }
  Problem problem(const ObjectEigen& object, const Excitation& excitation, double sample_rate_hz) const {
    return Problem{ref, object, excitation, sample_rate_hz, frames, prune, noise, floor_amp, noise_sigma};
  }
};

}  // namespace

PerceptualScores score_candidate(const std::vector<float>& recording, double sample_rate_hz,
                                 const std::vector<Mode>& modes, const ObjectEigen& object, const Excitation& excitation,
                                 const Candidate& candidate, double contact_s, const EstimateOptions& options) {
  const Setup setup(recording, sample_rate_hz, modes, options);
  return setup.problem(object, excitation, sample_rate_hz).score(candidate, contact_s);
}

MaterialEstimate estimate_material(const std::vector<float>& recording, double sample_rate_hz,
                                   const std::vector<Mode>& modes, const ObjectEigen& object,
                                   const Excitation& excitation, const EstimateOptions& options) {
  const Setup setup(recording, sample_rate_hz, modes, options);
  const PerceptualReference& ref = setup.ref;
  const std::size_t frames = setup.frames;
  std::vector<double> weights;
  for (const FeaturePoint& p : ref.features()) weights.push_back(p.weight);
  const std::vector<StartPoint> starts =
      start_points(modes, weights, object.lambda0, object.gain, options.dominant_modes, options.start_eigenvalues);
  if (starts.empty()) throw std::invalid_argument("no start point (fewer than two usable modes in the recording)");

  const Problem problem = setup.problem(object, excitation, sample_rate_hz);
  const bool fit_contact = options.fit_contact && excitation.shape != PulseShape::impulse;
  const double contact0 =
      std::clamp(excitation.contact_s, options.min_contact_s, options.max_contact_s);
  const std::vector<std::size_t> chosen = choose_starts(starts, problem, excitation.contact_s, modes, weights, options);

  MaterialEstimate out;
  out.frames = frames;
  out.contact_s = excitation.contact_s;
  auto contact_of = [&](const std::vector<double>& x) { return fit_contact ? std::exp(x[4]) : excitation.contact_s; };
  auto search = [&](const std::vector<double>& x0, const BoxedSearchOptions& o) {
    return nelder_mead_boxed(
        [&](const std::vector<double>& x) { return problem.score(from_log(x), contact_of(x)).hybrid; }, x0, o);
  };
  // Screening: a short search from each start, so that a start of the wrong gamma costs little.
  std::vector<BoxedSearchResult> screened;
  std::vector<BoxedSearchOptions> boxes;
  for (const std::size_t i : chosen) {
    StartResult s;
    s.start = starts[i];
    s.initial = initial_candidate(starts[i]);
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
    o.max_evaluations = std::min(options.screen_evaluations, options.max_evaluations);
    screened.push_back(search(x0, o));
    boxes.push_back(o);
    out.starts.push_back(s);
  }
  // Refinement: the best screened starts searched on (a fresh simplex round the screened point).
  std::vector<std::size_t> order(chosen.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t p, std::size_t q) { return screened[p].value < screened[q].value; });
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t j = order[k];
    BoxedSearchResult r = screened[j];
    if (k < options.refined_starts && options.max_evaluations > r.evaluations) {
      BoxedSearchOptions o = boxes[j];
      o.max_evaluations = options.max_evaluations - r.evaluations;
      const BoxedSearchResult more = search(r.x, o);
      if (more.value <= r.value) r.x = more.x, r.value = more.value;
      r.iterations += more.iterations;
      r.evaluations += more.evaluations;
    }
    StartResult& s = out.starts[j];
    s.fitted = from_log(r.x);
    s.contact_s = contact_of(r.x);
    s.scores = problem.score(s.fitted, s.contact_s);
    s.iterations = r.iterations;
    s.evaluations = r.evaluations;
    out.iterations += r.iterations;
  }
  double best = HUGE_VAL;
  for (const StartResult& s : out.starts)
    if (s.scores.hybrid < best) {
      best = s.scores.hybrid;
      out.material = s.fitted;
      out.contact_s = s.contact_s;
      out.scores = s.scores;
    }
  out.hybrid_minimum = out.material;
  if (options.polish_evaluations > 0 && std::isfinite(best)) {
    std::vector<double> x0 = to_log(out.material);
    if (fit_contact) x0.push_back(std::log(out.contact_s));
    const double factor = std::log(1.5), gamma_range = std::log(1.02);
    BoxedSearchOptions o;
    for (std::size_t i = 0; i < x0.size(); ++i) {
      const double range = i == 2 ? gamma_range : factor;
      o.lower.push_back(x0[i] - range);
      o.upper.push_back(x0[i] + range);
      o.step.push_back(0.1 * range);
    }
    if (fit_contact) {
      o.lower[4] = std::max(o.lower[4], std::log(options.min_contact_s));
      o.upper[4] = std::min(o.upper[4], std::log(options.max_contact_s));
    }
    o.max_evaluations = options.polish_evaluations;
    const BoxedSearchResult r = nelder_mead_boxed(
        [&](const std::vector<double>& x) { return problem.score(from_log(x), contact_of(x)).psycho; }, x0, o);
    out.polish_evaluations = r.evaluations;
    if (r.value < out.scores.psycho) {
      out.material = from_log(r.x);
      out.contact_s = contact_of(r.x);
      out.scores = problem.score(out.material, out.contact_s);
    }
  }
  out.matched_modes = matched(ref.features(), candidate_model(object, out.material, 0.5 * sample_rate_hz).modes,
                              options.perceptual.match);
  return out;
}

}  // namespace ms
