// The synthetic validation of Sterling et al. 2019 (sec. 1.3.3, Fig. 1.12), end to end on sounds:
// strikes of objects made of a known Rayleigh material are rendered (15 modes log-uniform in
// 100 Hz-15 kHz, gains over 30 dB, a new object per strike as in the paper; every mode gets a one-sided
// support excess Exp(mean) with the mean drawn per strike, 0.125-0.5 alpha1 in d, the paper's model of
// supports), white noise at a stated SNR is added, the modes are extracted by extract_features, and
// the damping law is fitted from the features of a growing number of strikes by each estimator. The
// result is the median relative error of alpha1 and of alpha2 per number of sounds and estimator,
// over resamples of the strike pool: Fig. 1.12's two panels.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/damping/damping_features.hpp"
#include "analysis/damping/damping_fit.hpp"
#include "synthesis/damping_law.hpp"

namespace ms {

struct SyntheticStrikeOptions {
  double sample_rate_hz = 44100.0;
  double seconds = 1.5;
  double snr_db = 40.0;  // noise power below the mean power of the whole clean strike
};

// The damping points extracted from `count` strikes of objects made of `law`'s material, one vector
// per strike; strike s depends only on (seed, s), so a pool can be grown without changing its start.
std::vector<std::vector<DampingPoint>> synthetic_strikes(const DampingLaw& law, std::size_t count,
                                                         std::uint64_t seed, const SyntheticStrikeOptions& options = {});

// One estimator as the validation runs it.
struct ValidatedEstimator {
  std::string name;  // "lsq", "lb", "emg", "emg-relative"
  DampingEstimator estimator = DampingEstimator::lsq;
  bool relative_noise = false;
};
// LSQ, LB, the published EMG (one normal spread) and EMG with a spread proportional to c.
std::vector<ValidatedEstimator> validated_estimators();

struct SyntheticValidationOptions {
  std::vector<std::size_t> sound_counts{1, 2, 5, 10, 20, 40};
  std::size_t resamples = 30;      // draws of that many strikes from the pool, per count
  std::uint64_t seed = 2019;       // the strike pool
  std::uint64_t resample_seed = 7;
  SyntheticStrikeOptions strikes;
};

struct ValidationCurve {
  ValidatedEstimator estimator;
  std::vector<double> alpha1_median_rel_error;  // one per sound count
  std::vector<double> alpha2_median_rel_error;
};

struct SyntheticValidation {
  DampingLaw truth;
  std::vector<std::size_t> sound_counts;
  std::vector<ValidationCurve> curves;  // in validated_estimators() order
  // Per count and estimator, every resample's relative errors (for paired tests between estimators):
  // errors_alpha1[count][estimator][resample].
  std::vector<std::vector<std::vector<double>>> errors_alpha1, errors_alpha2;
};

// Runs the validation on a pool of max(sound_counts) strikes. Throws std::invalid_argument for an empty
// or zero count, or a law that is not Rayleigh with alpha1, alpha2 > 0.
SyntheticValidation run_synthetic_validation(const DampingLaw& truth, const SyntheticValidationOptions& options);

}  // namespace ms
