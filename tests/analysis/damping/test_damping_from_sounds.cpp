// The published synthetic validation (Sterling et al. 2019, sec. 1.3.3) run end to end on SOUNDS
// (synthetic_strikes): each strike is rendered (a known Rayleigh material plus a random one-sided
// support damping per strike, 40 dB SNR), its modes are extracted by extract_features, and the
// features of 10-40 strikes are fitted by each estimator. Unlike test_damping_fit.cpp (features drawn from the model), the
// decays here carry the extractor's own errors and spurious modes.
// What it shows: LB beats LSQ for both materials (p < 1e-8). The published EMG (one normal sigma)
// beats LSQ for steel but NOT for glass: the extractor's decay errors grow with the decay (+-20 1/s
// around c = 300 1/s at 10 kHz, +-0.2 at 100 Hz), so one sigma is set by the fast modes (~16 1/s) and
// swamps the support damping excess (~1 1/s) that fixes alpha1 (its likelihood optimum itself is off:
// run to convergence it puts alpha1 below zero). EMG with a spread proportional to c
// (DampingFitOptions::relative_noise, `fit-damping --noise relative`) beats LSQ for both, with median
// alpha1 errors of 2-3 %, as good as LB, and unlike LB it also survives low outliers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>

#include "analysis/damping/damping_fit.hpp"
#include "analysis/damping/synthetic_validation.hpp"
#include "analysis/stats/wilcoxon.hpp"
#include "synthesis/material.hpp"

namespace ms {
namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return 0.5 * (v[(v.size() - 1) / 2] + v[v.size() / 2]);
}

class DampingFromSounds : public ::testing::TestWithParam<const char*> {};

TEST_P(DampingFromSounds, SyntheticValidationOnExtractedFeatures) {
  const DampingLaw law = find_material(GetParam())->rayleigh;
  const auto pool = synthetic_strikes(law, 40, 2019);
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::size_t> how_many(10, 40);
  std::vector<double> emg, emg_rel, lb, lsq;
  for (int r = 0; r < 30; ++r) {  // 30 resamples of 10-40 strikes
    std::vector<std::size_t> ids(pool.size());
    std::iota(ids.begin(), ids.end(), std::size_t{0});
    std::shuffle(ids.begin(), ids.end(), rng);
    std::vector<DampingPoint> pts;
    const std::size_t n = how_many(rng);
    for (std::size_t i = 0; i < n; ++i) pts.insert(pts.end(), pool[ids[i]].begin(), pool[ids[i]].end());
    auto err = [&](DampingEstimator e, const DampingFitOptions& options = {}) {
      return std::abs(fit_damping(pts, DampingKind::rayleigh, e, options).law.alpha1 - law.alpha1) / law.alpha1;
    };
    emg.push_back(err(DampingEstimator::emg));
    DampingFitOptions relative;
    relative.relative_noise = true;
    emg_rel.push_back(err(DampingEstimator::emg, relative));
    lb.push_back(err(DampingEstimator::lb));
    lsq.push_back(err(DampingEstimator::lsq));
  }
  WilcoxonOptions greater;
  greater.alternative = Alternative::greater;
  const double p_emg = wilcoxon_signed_rank(lsq, emg, greater).p;
  const double p_lb = wilcoxon_signed_rank(lsq, lb, greater).p;
  const double p_rel = wilcoxon_signed_rank(lsq, emg_rel, greater).p;
  std::printf("%s from extracted sounds: median rel. error alpha1  emg %.4f  emg relative noise %.4f  lb %.4f  "
              "lsq %.4f;  p(lsq>emg) %.2e  p(lsq>emg relative) %.2e  p(lsq>lb) %.2e\n",
              GetParam(), median(emg), median(emg_rel), median(lb), median(lsq), p_emg, p_rel, p_lb);
  EXPECT_LT(p_lb, 0.01);
  EXPECT_LT(median(lb), 0.1);
  EXPECT_LT(p_rel, 0.01);
  EXPECT_LT(median(emg_rel), 0.1);
  if (std::string(GetParam()) == "sterling2019/steel") EXPECT_LT(p_emg, 0.01);
  else EXPECT_GT(median(emg), 5.0 * median(emg_rel));  // glass: the constant-sigma failure, kept visible
}

INSTANTIATE_TEST_SUITE_P(Materials, DampingFromSounds,
                         ::testing::Values("sterling2019/steel", "sterling2019/glass"), [](const auto& info) {
                           std::string s = info.param;
                           return s.substr(s.find('/') + 1);
                         });

}  // namespace
}  // namespace ms
