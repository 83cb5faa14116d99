#include "analysis/damping/synthetic_validation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <stdexcept>

#include "analysis/extraction/feature_extraction.hpp"
#include "synthesis/effects.hpp"
#include "synthesis/reference_renderer.hpp"

namespace ms {
namespace {

// The clean strike (exact reference renderer) plus white noise snr_db below its mean power.
std::vector<float> noisy_strike(const ModalModel& model, const SyntheticStrikeOptions& o, std::uint64_t noise_seed) {
  const auto frames = std::size_t(o.seconds * o.sample_rate_hz);
  const std::vector<double> clean = render_reference(model, {}, o.sample_rate_hz, frames);
  double power = 0.0;
  for (double v : clean) power += v * v;
  power /= double(frames);
  std::mt19937_64 rng(noise_seed ^ 0x9e3779b97f4a7c15ULL);
  std::normal_distribution<double> noise(0.0, std::sqrt(power / std::pow(10.0, o.snr_db / 10.0)));
  std::vector<float> out(frames);
  for (std::size_t n = 0; n < frames; ++n) out[n] = float(clean[n] + noise(rng));
  return out;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
}

}  // namespace

std::vector<std::vector<DampingPoint>> synthetic_strikes(const DampingLaw& law, std::size_t count,
                                                         std::uint64_t seed, const SyntheticStrikeOptions& options) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::vector<DampingPoint>> strikes;
  for (std::size_t s = 0; s < count; ++s) {
    std::vector<double> lambdas, gains;
    for (int i = 0; i < 15; ++i) {
      lambdas.push_back(std::pow(2.0 * std::numbers::pi * 100.0 * std::pow(150.0, unit(rng)), 2));
      gains.push_back(std::pow(10.0, -30.0 * unit(rng) / 20.0));
    }
    ModalModel model = modes_from_eigenvalues(lambdas, law, 1.0, 0.3, gains, nullptr);
    SupportDamping support;
    support.exponential_mean_per_s = 0.5 * (0.25 + 0.75 * unit(rng)) * law.alpha1;
    support.seed = rng();
    apply_support_damping(model, support);
    const std::vector<float> x = noisy_strike(model, options, seed * 1000 + s);
    std::vector<DampingPoint> points;
    for (const Mode& m : extract_features(x, options.sample_rate_hz).modes)
      points.push_back(damping_point(m.freq_hz, m.decay_per_s));
    strikes.push_back(std::move(points));
  }
  return strikes;
}

std::vector<ValidatedEstimator> validated_estimators() {
  return {{"lsq", DampingEstimator::lsq, false},
          {"lb", DampingEstimator::lb, false},
          {"emg", DampingEstimator::emg, false},
          {"emg-relative", DampingEstimator::emg, true}};
}

SyntheticValidation run_synthetic_validation(const DampingLaw& truth, const SyntheticValidationOptions& options) {
  if (truth.kind != DampingKind::rayleigh || !(truth.alpha1 > 0) || !(truth.alpha2 > 0))
    throw std::invalid_argument("synthetic validation needs a Rayleigh law with alpha1 > 0 and alpha2 > 0");
  if (options.sound_counts.empty() || options.resamples == 0)
    throw std::invalid_argument("synthetic validation needs at least one sound count and one resample");
  for (std::size_t n : options.sound_counts)
    if (n == 0) throw std::invalid_argument("a sound count must be at least 1");
  const std::size_t pool_size = *std::max_element(options.sound_counts.begin(), options.sound_counts.end());
  const auto pool = synthetic_strikes(truth, pool_size, options.seed, options.strikes);
  const std::vector<ValidatedEstimator> estimators = validated_estimators();

  SyntheticValidation out;
  out.truth = truth;
  out.sound_counts = options.sound_counts;
  for (const auto& e : estimators) out.curves.push_back({e, {}, {}});
  std::mt19937_64 rng(options.resample_seed);
  std::vector<std::size_t> ids(pool.size());
  for (std::size_t n : options.sound_counts) {
    std::vector<std::vector<double>> err1(estimators.size()), err2(estimators.size());
    for (std::size_t r = 0; r < options.resamples; ++r) {
      std::iota(ids.begin(), ids.end(), std::size_t{0});
      std::shuffle(ids.begin(), ids.end(), rng);
      std::vector<DampingPoint> points;
      for (std::size_t i = 0; i < n; ++i) points.insert(points.end(), pool[ids[i]].begin(), pool[ids[i]].end());
      for (std::size_t k = 0; k < estimators.size(); ++k) {
        DampingFitOptions fit_options;
        fit_options.relative_noise = estimators[k].relative_noise;
        const bool enough = points.size() >= damping_fit_param_count(DampingKind::rayleigh, estimators[k].estimator);
        const DampingLaw fitted =
            enough ? fit_damping(points, DampingKind::rayleigh, estimators[k].estimator, fit_options).law : DampingLaw{};
        // Too few modes to fit: the estimate is missing, an error of 100 %.
        err1[k].push_back(enough ? std::abs(fitted.alpha1 - truth.alpha1) / truth.alpha1 : 1.0);
        err2[k].push_back(enough ? std::abs(fitted.alpha2 - truth.alpha2) / truth.alpha2 : 1.0);
      }
    }
    for (std::size_t k = 0; k < estimators.size(); ++k) {
      out.curves[k].alpha1_median_rel_error.push_back(median(err1[k]));
      out.curves[k].alpha2_median_rel_error.push_back(median(err2[k]));
    }
    out.errors_alpha1.push_back(std::move(err1));
    out.errors_alpha2.push_back(std::move(err2));
  }
  return out;
}

}  // namespace ms
