// Fig. 1.12 of Sterling et al. 2019: the relative error of BOTH Rayleigh parameters against the
// number of sounds the estimate uses, for each estimator (run_synthetic_validation, end to end on
// rendered and extracted strikes).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "analysis/damping/synthetic_validation.hpp"
#include "analysis/stats/wilcoxon.hpp"
#include "synthesis/material.hpp"

namespace ms {
namespace {

std::size_t index_of(const SyntheticValidation& v, const std::string& name) {
  for (std::size_t k = 0; k < v.curves.size(); ++k)
    if (v.curves[k].estimator.name == name) return k;
  ADD_FAILURE() << "no estimator " << name;
  return 0;
}

TEST(SyntheticValidation, ErrorOfBothParametersAgainstTheNumberOfSounds) {
  const DampingLaw steel = find_material("sterling2019/steel")->rayleigh;
  SyntheticValidationOptions options;
  options.sound_counts = {1, 4, 16};
  options.resamples = 15;
  const SyntheticValidation v = run_synthetic_validation(steel, options);
  ASSERT_EQ(v.curves.size(), 4u);
  for (const auto& c : v.curves) {
    ASSERT_EQ(c.alpha1_median_rel_error.size(), 3u);
    ASSERT_EQ(c.alpha2_median_rel_error.size(), 3u);
    std::printf("%-13s alpha1 %.4f %.4f %.4f   alpha2 %.4f %.4f %.4f\n", c.estimator.name.c_str(),
                c.alpha1_median_rel_error[0], c.alpha1_median_rel_error[1], c.alpha1_median_rel_error[2],
                c.alpha2_median_rel_error[0], c.alpha2_median_rel_error[1], c.alpha2_median_rel_error[2]);
    for (double e : c.alpha2_median_rel_error) EXPECT_TRUE(std::isfinite(e));
  }
  const std::size_t lsq = index_of(v, "lsq"), lb = index_of(v, "lb"), rel = index_of(v, "emg-relative");
  // More sounds, smaller alpha1 error for the estimators that model the support excess (Fig. 1.12 left).
  for (std::size_t k : {lb, rel})
    EXPECT_LT(v.curves[k].alpha1_median_rel_error[2], v.curves[k].alpha1_median_rel_error[0])
        << v.curves[k].estimator.name;
  // With 16 sounds both beat LSQ on alpha1 in paired resamples (the paper: p < .05).
  WilcoxonOptions greater;
  greater.alternative = Alternative::greater;
  for (std::size_t k : {lb, rel})
    EXPECT_LT(wilcoxon_signed_rank(v.errors_alpha1[2][lsq], v.errors_alpha1[2][k], greater).p, 0.05)
        << v.curves[k].estimator.name;
  // alpha2 (the stiffness-proportional part, set by the many fast modes): LSQ and EMG with a relative
  // spread stay within a few per cent; LB's error GROWS with the number of sounds (0.3 % -> 22 % here),
  // the overfitting of alpha2 the paper's caption reports: a lower bound follows the lowest of ever
  // more extracted decays.
  for (std::size_t k : {lsq, rel}) EXPECT_LT(v.curves[k].alpha2_median_rel_error[2], 0.05) << v.curves[k].estimator.name;
  EXPECT_GT(v.curves[lb].alpha2_median_rel_error[2], 5 * v.curves[lb].alpha2_median_rel_error[0]);
}

TEST(SyntheticValidation, RefusesWhatItCannotRun) {
  const DampingLaw steel = find_material("sterling2019/steel")->rayleigh;
  SyntheticValidationOptions none;
  none.sound_counts = {};
  EXPECT_THROW(run_synthetic_validation(steel, none), std::invalid_argument);
  SyntheticValidationOptions zero;
  zero.sound_counts = {0, 2};
  EXPECT_THROW(run_synthetic_validation(steel, zero), std::invalid_argument);
  DampingLaw power = steel;
  power.kind = DampingKind::powerlaw;
  EXPECT_THROW(run_synthetic_validation(power, {}), std::invalid_argument);
}

TEST(SyntheticValidation, StrikesDependOnlyOnSeedAndIndex) {
  const DampingLaw glass = find_material("sterling2019/glass")->rayleigh;
  const auto three = synthetic_strikes(glass, 3, 11);
  const auto two = synthetic_strikes(glass, 2, 11);
  ASSERT_EQ(two.size(), 2u);
  for (std::size_t s = 0; s < 2; ++s) {
    ASSERT_EQ(two[s].size(), three[s].size());
    for (std::size_t i = 0; i < two[s].size(); ++i) EXPECT_EQ(two[s][i].c_per_s, three[s][i].c_per_s);
  }
  EXPECT_GE(three[2].size(), 5u);  // the modes of a strike are found
}

}  // namespace
}  // namespace ms
