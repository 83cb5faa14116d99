// The material estimation on synthetic recordings of the reference bar and plate, and its bounded local search.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/estimation/estimate_material.hpp"
#include "analysis/estimation/local_search.hpp"
#include "analysis/extraction/feature_extraction.hpp"
#include "synthesis/material.hpp"
#include "synthesis/reference_objects.hpp"

namespace ms {
namespace {

TEST(EstimateLocalSearch, FindsTheMinimumOfAShiftedQuadraticInsideTheBox) {
  BoxedSearchOptions o;
  o.lower = {-5, -5};
  o.upper = {5, 5};
  o.step = {0.5, 0.5};
  o.max_evaluations = 400;
  const auto r = nelder_mead_boxed(
      [](const std::vector<double>& x) { return std::pow(x[0] - 1.5, 2) + 3 * std::pow(x[1] + 2.0, 2); }, {0, 0}, o);
  EXPECT_NEAR(r.x[0], 1.5, 1e-3);
  EXPECT_NEAR(r.x[1], -2.0, 1e-3);
  EXPECT_GT(r.iterations, 0u);
  EXPECT_LE(r.evaluations, 400u);
}

TEST(EstimateLocalSearch, StaysOnTheBoxFaceWhenTheMinimumLiesOutside) {
  BoxedSearchOptions o;
  o.lower = {0, 0};
  o.upper = {1, 1};
  o.step = {0.2, 0.2};
  const auto r = nelder_mead_boxed(
      [](const std::vector<double>& x) { return std::pow(x[0] - 3, 2) + std::pow(x[1] - 0.5, 2); }, {0.5, 0.5}, o);
  EXPECT_NEAR(r.x[0], 1.0, 1e-4);
  EXPECT_NEAR(r.x[1], 0.5, 1e-3);
}

ObjectEigen bar_object() {
  const ObjectModes om = free_free_bar(0.25, 0.012, {0.1}, 1e12, 30);
  return {om.lambda0, om.gains[0]};
}

TEST(EstimateObject, AParameterSetsBarGivesTheReferenceBarsEigenvaluesWhateverItsMaterial) {
  const ObjectEigen set = object_eigen_from_paramset(MODALSTUDY_SOURCE_DIR "/stimuli/bar/ren-wood.yaml");
  const ObjectEigen bar = bar_object();
  ASSERT_GE(set.lambda0.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR(set.lambda0[i] / bar.lambda0[i], 1.0, 1e-6) << i;
    EXPECT_NEAR(set.gain[i], bar.gain[i], 1e-6 * std::abs(bar.gain[i]) + 1e-12) << i;
  }
}

ObjectEigen plate_object() {
  const ObjectModes om = free_circular_plate(0.10, 0.003, 0.33, {0.3}, 1e12, 60);
  return {om.lambda0, om.gains[0]};
}

struct RenCase {
  const char* material;
  bool plate;
};

class EstimateRenMaterial : public ::testing::TestWithParam<RenCase> {};

// The loudest mode of plastic, glass and porcelain is not on the excitation's Pareto set (on the bar
// it is the fifth, fifth and second mode); the starts map it onto every eigenvalue so that one of them
// has the right gamma.
TEST_P(EstimateRenMaterial, RecoversItFromANoiseFreeRender) {
  const Material& m = *find_material(std::string("ren2013/") + GetParam().material);
  const double fs = 44100;
  const ObjectEigen object = GetParam().plate ? plate_object() : bar_object();
  const Candidate truth{m.rayleigh.alpha1, m.rayleigh.alpha2, m.specific_modulus_m2_s2, 0.01};
  const Excitation impulse;
  const auto x = render_candidate(candidate_model(object, truth, fs / 2), impulse, fs, std::size_t(fs));
  const ExtractedFeatures f = extract_features(x, fs);
  ASSERT_GE(f.modes.size(), 3u);
  const MaterialEstimate e = estimate_material(x, fs, f.modes, object, impulse);
  ASSERT_FALSE(e.starts.empty());
  EXPECT_NEAR(e.material.gamma / truth.gamma, 1.0, 0.02);
  EXPECT_NEAR(e.material.alpha / truth.alpha, 1.0, 0.10);
  EXPECT_NEAR(e.material.beta / truth.beta, 1.0, 0.10);
  EXPECT_NEAR(e.material.sigma / truth.sigma, 1.0, 0.10);
  EXPECT_GE(e.matched_modes, 3u);
  // The truth itself scores at least as low as the estimate (the metric's minimum is at the truth).
  const PerceptualReference ref(x, fs, f.modes);
  const ModalModel t = candidate_model(object, truth, fs / 2);
  EXPECT_LE(ref.compare(x, t.modes).hybrid, e.scores.hybrid * (1 + 1e-9));
}

TEST(EstimateRenMaterial, ParetoStartsAloneMissPlasticOnTheBar) {
  const Material& m = *find_material("ren2013/plastic");
  const double fs = 44100;
  const ObjectEigen bar = bar_object();
  const Candidate truth{m.rayleigh.alpha1, m.rayleigh.alpha2, m.specific_modulus_m2_s2, 0.01};
  const auto x = render_candidate(candidate_model(bar, truth, fs / 2), {}, fs, std::size_t(fs));
  const ExtractedFeatures f = extract_features(x, fs);
  EstimateOptions o;
  o.start_eigenvalues = StartEigenvalues::pareto;
  o.max_starts = 1;
  EXPECT_GT(std::abs(estimate_material(x, fs, f.modes, bar, {}, o).material.gamma / truth.gamma - 1.0), 0.2);
}

std::string ren_case_name(const ::testing::TestParamInfo<RenCase>& info) {
  return std::string(info.param.material) + (info.param.plate ? "_plate" : "_bar");
}

INSTANTIATE_TEST_SUITE_P(Ren, EstimateRenMaterial,
                         ::testing::Values(RenCase{"wood", false}, RenCase{"plastic", false}, RenCase{"metal", false},
                                           RenCase{"glass", false}, RenCase{"porcelain", false},
                                           RenCase{"wood", true}, RenCase{"plastic", true}, RenCase{"metal", true},
                                           RenCase{"glass", true}, RenCase{"porcelain", true}),
                         ren_case_name);

}  // namespace
}  // namespace ms
