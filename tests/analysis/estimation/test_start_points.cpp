// Starting points of the material estimation (analysis/estimation/start_points.hpp): the Rayleigh
// circle through two modes of a known material gives back its alpha and beta, the inverse map from a
// frequency to an eigenvalue, the Pareto set of eigenvalues on a hand-made set, and a start that
// reproduces the true {alpha, beta, gamma/gamma0, sigma} when the right eigenvalue meets the dominant mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/estimation/start_points.hpp"
#include "synthesis/damping_law.hpp"

using namespace ms;

namespace {

// Ren 2013's wood (DESIGN.md 3): alpha 2.1364 1/s, beta 3.0828e-6 s.
constexpr double kAlpha = 2.1364, kBeta = 3.0828e-6, kRatio = 1.7, kSigma = 0.3;

DampingLaw rayleigh(double alpha, double beta) {
  DampingLaw law;
  law.kind = DampingKind::rayleigh;
  law.alpha1 = alpha;
  law.alpha2 = beta;
  return law;
}

std::vector<double> eigenvalues() {
  std::vector<double> l;
  for (double f : {400.0, 1100.0, 2300.0, 3900.0, 6100.0}) l.push_back(std::pow(2.0 * std::numbers::pi * f, 2));
  return l;
}
const std::vector<double> kGains = {0.5, -1.0, 0.3, 0.8, 0.2};

std::vector<Mode> true_modes() {
  return modes_from_eigenvalues(eigenvalues(), rayleigh(kAlpha, kBeta), kRatio, kSigma, kGains, nullptr).modes;
}

}  // namespace

TEST(StartPoints, CircleThroughTwoModesGivesTheMaterialBack) {
  const std::vector<Mode> m = true_modes();
  ASSERT_EQ(m.size(), 5u);
  for (auto [i, j] : {std::pair{0, 3}, std::pair{1, 2}, std::pair{4, 0}}) {
    const auto c = rayleigh_circle_through(m[std::size_t(i)], m[std::size_t(j)]);
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->alpha, kAlpha, 1e-7 * kAlpha) << i << "," << j;
    EXPECT_NEAR(c->beta, kBeta, 1e-9 * kBeta) << i << "," << j;
  }
  // Both points on it: Eq. 8, omega^2 + (d - 1/beta)^2 = (1 - alpha beta) / beta^2.
  const auto c = rayleigh_circle_through(m[0], m[3]);
  for (const Mode& md : m) {
    const double w = 2.0 * std::numbers::pi * md.freq_hz, r = md.decay_per_s - 1.0 / c->beta;
    EXPECT_NEAR((w * w + r * r) * c->beta * c->beta, 1.0 - c->alpha * c->beta, 1e-9);
  }
}

TEST(StartPoints, CirclesNoMaterialHasAreRefused) {
  // The higher mode decays more slowly: beta < 0.
  EXPECT_FALSE(rayleigh_circle_through({500.0, 20.0, 1.0, 0.0}, {1500.0, 5.0, 1.0, 0.0}));
  // Same eigenvalue: no line.
  EXPECT_FALSE(rayleigh_circle_through({500.0, 20.0, 1.0, 0.0}, {500.0, 20.0, 0.5, 0.0}));
  // Decay growing faster than lambda allows with alpha >= 0 (the line meets lambda = 0 below 0).
  EXPECT_FALSE(rayleigh_circle_through({500.0, 1.0, 1.0, 0.0}, {1000.0, 100.0, 1.0, 0.0}));
}

TEST(StartPoints, TheNearestPhysicalCircleHoldsTheNegativeCoefficientAtZero) {
  const std::vector<Mode> m = true_modes();
  // A physical circle is the exact one.
  const RayleighCircle exact = nearest_physical_circle(m[0], m[3]);
  EXPECT_NEAR(exact.alpha, kAlpha, 1e-7 * kAlpha);
  EXPECT_NEAR(exact.beta, kBeta, 1e-9 * kBeta);
  // The upper mode decays more slowly: beta 0, alpha the mean of c = 2d.
  const RayleighCircle flat = nearest_physical_circle({500.0, 20.0, 1.0, 0.0}, {1500.0, 5.0, 1.0, 0.0});
  EXPECT_EQ(flat.beta, 0.0);
  EXPECT_NEAR(flat.alpha, 25.0, 1e-12);
  // Decay growing faster than lambda: alpha 0, beta the least-squares slope through the origin.
  const Mode a{500.0, 1.0, 1.0, 0.0}, b{1000.0, 100.0, 1.0, 0.0};
  const RayleighCircle origin = nearest_physical_circle(a, b);
  EXPECT_EQ(origin.alpha, 0.0);
  const auto lambda = [](const Mode& x) {
    const double w = 2.0 * std::numbers::pi * x.freq_hz;
    return w * w + x.decay_per_s * x.decay_per_s;
  };
  const double la = lambda(a), lb = lambda(b);
  EXPECT_NEAR(origin.beta, (2.0 * la + 200.0 * lb) / (la * la + lb * lb), 1e-12 * origin.beta);
  // Either way every decay keeps a start: the eigenvalue map reaches the dominant mode.
  EXPECT_TRUE(eigenvalue_for_frequency(origin, 1000.0));
  EXPECT_TRUE(eigenvalue_for_frequency(flat, 1500.0));
}

TEST(StartPoints, EigenvalueForFrequencyInvertsTheMap) {
  const RayleighCircle c{kAlpha, kBeta};
  const std::vector<double> l0 = eigenvalues();
  const std::vector<Mode> m = true_modes();
  for (std::size_t i = 0; i < m.size(); ++i) {
    const auto lambda = eigenvalue_for_frequency(c, m[i].freq_hz);
    ASSERT_TRUE(lambda);
    EXPECT_NEAR(*lambda, kRatio * l0[i], 1e-10 * kRatio * l0[i]);
  }
  // beta = 0: lambda = omega^2 + alpha^2/4.
  const double w = 2.0 * std::numbers::pi * 1000.0;
  EXPECT_NEAR(*eigenvalue_for_frequency({4.0, 0.0}, 1000.0), w * w + 4.0, 1e-6);
  // A circle too small for the frequency: 1 - alpha beta < beta^2 omega^2.
  EXPECT_FALSE(eigenvalue_for_frequency({10.0, 1e-3}, 1000.0));
}

TEST(StartPoints, ParetoEigenvalues) {
  // Not beaten by a smaller eigenvalue with a larger |excitation|: 0 (smallest), 1 (1.0 > 0.5), 4.
  EXPECT_EQ(pareto_eigenvalues({1, 2, 3, 4, 5}, {0.5, 1.0, 0.3, 0.8, 2.0}), (std::vector<std::size_t>{0, 1, 4}));
  // Order of the input does not matter; signs are phases; ties survive; zero excitation cannot be scaled.
  EXPECT_EQ(pareto_eigenvalues({5, 3, 1, 2}, {-2.0, 0.3, 0.5, -1.0}), (std::vector<std::size_t>{2, 3, 0}));
  EXPECT_EQ(pareto_eigenvalues({1, 2}, {0.5, 0.5}), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(pareto_eigenvalues({1, 2}, {0.0, 0.5}), (std::vector<std::size_t>{1}));
  EXPECT_THROW(pareto_eigenvalues({1, 2}, {1.0}), std::invalid_argument);
}

TEST(StartPoints, OneStartIsTheTrueMaterial) {
  const std::vector<Mode> m = true_modes();
  const std::vector<double> l0 = eigenvalues();
  // Mode 1 (gain -1) is the most dominant; then 3, 0, 2, 4.
  const std::vector<double> weights = {3.0, 10.0, 2.0, 5.0, 1.0};
  const std::vector<StartPoint> starts = start_points(m, weights, l0, kGains, 3);
  // Pairs of {1, 3, 0}: 3 circles, each with the Pareto eigenvalues 0 (0.5), 1 (1.0).
  ASSERT_EQ(starts.size(), 3u * 2u);
  bool found = false;
  for (const StartPoint& s : starts) {
    // Every start puts its eigenvalue on the dominant mode's frequency and amplitude.
    const ModalModel mapped = modes_from_eigenvalues(l0, rayleigh(s.circle.alpha, s.circle.beta), s.stiffness_ratio,
                                                     s.amp_scale, kGains, nullptr);
    ASSERT_EQ(mapped.modes.size(), l0.size());
    EXPECT_NEAR(mapped.modes[s.eigenvalue].freq_hz, m[1].freq_hz, 1e-9 * m[1].freq_hz);
    EXPECT_NEAR(mapped.modes[s.eigenvalue].amp, m[1].amp, 1e-12);
    if (s.eigenvalue == 1) {
      found = true;
      EXPECT_NEAR(s.circle.alpha, kAlpha, 1e-7 * kAlpha);
      EXPECT_NEAR(s.circle.beta, kBeta, 1e-9 * kBeta);
      EXPECT_NEAR(s.stiffness_ratio, kRatio, 1e-9 * kRatio);
      EXPECT_NEAR(s.amp_scale, kSigma, 1e-12);
    }
  }
  EXPECT_TRUE(found);
  // Mapped onto every eigenvalue: the same 3 circles times the 5 distinct eigenvalues.
  EXPECT_EQ(start_points(m, weights, l0, kGains, 3, StartEigenvalues::every).size(), 3u * 5u);
  EXPECT_TRUE(start_points({}, {}, l0, kGains).empty());
  EXPECT_THROW(start_points(m, {1.0}, l0, kGains), std::invalid_argument);
}

TEST(StartPoints, ADominantModeOffTheParetoSetGetsItsTrueStartOnlyFromEveryEigenvalue) {
  const std::vector<Mode> m = true_modes();
  const std::vector<double> l0 = eigenvalues();
  // Mode 3 (gain 0.8, below mode 1's 1.0 at a smaller eigenvalue) is the most dominant.
  const std::vector<double> weights = {3.0, 2.0, 1.0, 10.0, 0.5};
  auto has_truth = [&](const std::vector<StartPoint>& starts) {
    return std::any_of(starts.begin(), starts.end(), [](const StartPoint& s) {
      return s.eigenvalue == 3 && std::abs(s.stiffness_ratio / kRatio - 1.0) < 1e-9;
    });
  };
  EXPECT_FALSE(has_truth(start_points(m, weights, l0, kGains, 3, StartEigenvalues::pareto)));
  EXPECT_TRUE(has_truth(start_points(m, weights, l0, kGains, 3, StartEigenvalues::every)));
}

TEST(StartPoints, EigenvalueAlignmentIsTheWeightedShareOfModesOnAnEigenvalue) {
  const std::vector<Mode> m = true_modes();
  const std::vector<double> l0 = eigenvalues();
  const std::vector<double> weights = {3.0, 10.0, 2.0, 5.0, 0.0};  // mode 4 weighs nothing
  // The true ratio puts every mode on its eigenvalue.
  EXPECT_DOUBLE_EQ(eigenvalue_alignment(m, weights, l0, kRatio), 1.0);
  // The ratio that maps mode 1 (the dominant) onto eigenvalue 2 lines up mode 1 alone: 2300/1100 is
  // not a ratio of any two other frequencies of the set within 0.4 % in eigenvalue.
  const double wrong = kRatio * l0[1] / l0[2];
  EXPECT_NEAR(eigenvalue_alignment(m, weights, l0, wrong), 10.0 / 20.0, 1e-12);
  // Off by 1 % in gamma (0.5 % in frequency), nothing lines up at the default tolerance; at 2 % all does.
  EXPECT_DOUBLE_EQ(eigenvalue_alignment(m, weights, l0, 1.01 * kRatio), 0.0);
  EXPECT_DOUBLE_EQ(eigenvalue_alignment(m, weights, l0, 1.01 * kRatio, 0.02), 1.0);
  EXPECT_DOUBLE_EQ(eigenvalue_alignment(m, {0, 0, 0, 0, 0}, l0, kRatio), 0.0);
  EXPECT_THROW(eigenvalue_alignment(m, {1.0}, l0, kRatio), std::invalid_argument);
}
