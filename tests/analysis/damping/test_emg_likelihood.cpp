// EMG log-likelihood: analytic gradient and Hessian against central finite differences for each law,
// the paper's Rayleigh gradient (eqs. 1.12-1.15, with n eta^2 sigma for the misprinted n lambda^2 sigma)
// against finite differences of the physical likelihood, and the scaled <-> physical mapping.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "analysis/damping/emg_likelihood.hpp"
#include "analysis/damping/log_erfc.hpp"

namespace {

using ms::DampingKind;
using ms::DampingLaw;
using ms::DampingPoint;

// Points from a law plus Exp(mean 3) excess plus N(0, 0.5) noise; f log-uniform 100 Hz - 15 kHz.
std::vector<DampingPoint> emg_points(const DampingLaw& law, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> logf(std::log(100.0), std::log(15000.0));
  std::exponential_distribution<double> excess(1.0 / 3.0);
  std::normal_distribution<double> noise(0.0, 0.5);
  std::vector<DampingPoint> pts;
  for (std::size_t i = 0; i < n; ++i) {
    const double omega = 2 * std::numbers::pi * std::exp(logf(rng));
    const double lambda = omega * omega;
    pts.push_back({lambda, ms::damping_c_per_s(law, lambda) + excess(rng) + noise(rng)});
  }
  return pts;
}

DampingLaw law_of(DampingKind kind) {
  DampingLaw law;  // Sterling's steel (hybrid numbers for powerlaw/hybrid)
  law.kind = kind;
  law.alpha1 = kind == DampingKind::powerlaw ? 0.0 : 2.4;
  law.alpha2 = kind == DampingKind::rayleigh ? 6.9e-8 : 5.5e-8;
  law.alpha3 = kind == DampingKind::rayleigh ? 1.0 : 1.011;
  return law;
}

class EmgLikelihoodLaw : public ::testing::TestWithParam<DampingKind> {};

// Checked for Sterling's constant spread and for a per-point spread (relative noise: spread
// proportional to the data, spanning two decades).
void check_derivatives(DampingKind kind, bool per_point_spread) {
  const auto pts = emg_points(law_of(kind), 300, 7);
  ms::EmgProblem pr = ms::make_emg_problem(pts, kind);
  if (per_point_spread)
    for (double y : pr.y) pr.noise_scale.push_back(std::max(y, 0.01));
  const int k = ms::law_param_count(kind);
  // A point away from the optimum, so the gradient is O(1)..O(n) rather than ~0.
  ms::EmgVector theta(k + 2);
  theta.head(k) = ms::scaled_from_law(pr, law_of(kind));
  theta.head(k) *= 1.05;
  theta[k] = std::log(0.02);
  theta[k + 1] = std::log(4.0);
  ms::EmgVector g;
  ms::EmgMatrix H;
  const double f = ms::emg_loglik_scaled(pr, theta, &g, &H);
  ASSERT_TRUE(std::isfinite(f));
  EXPECT_DOUBLE_EQ(f, ms::emg_loglik_scaled(pr, theta, nullptr, nullptr));
  // Fourth-order central differences, step 1e-4: rounding in the O(n) sums (terms up to ~1e3 when
  // r/sigma is large) and the O(h^4) truncation both stay well below the tolerance.
  const double h = 1e-4;
  auto shifted = [&](int j, double by) {
    ms::EmgVector t = theta;
    t[j] += by;
    return t;
  };
  for (int j = 0; j < k + 2; ++j) {
    auto f_at = [&](double by) { return ms::emg_loglik_scaled(pr, shifted(j, by), nullptr, nullptr); };
    const double fd = (8 * (f_at(h) - f_at(-h)) - (f_at(2 * h) - f_at(-2 * h))) / (12 * h);
    EXPECT_NEAR(g[j], fd, 1e-7 * std::max(1.0, std::abs(fd))) << "gradient " << j;
    auto g_at = [&](double by) {
      ms::EmgVector gg;
      ms::emg_loglik_scaled(pr, shifted(j, by), &gg, nullptr);
      return gg;
    };
    const ms::EmgVector fdh = (8 * (g_at(h) - g_at(-h)) - (g_at(2 * h) - g_at(-2 * h))) / (12 * h);
    // Small entries beside ~1e7 ones carry ~1e-11 relative rounding of the largest: allow for it.
    for (int l = 0; l < k + 2; ++l)
      EXPECT_NEAR(H(l, j), fdh[l], 1e-6 * std::max(1.0, std::abs(fdh[l])) + 1e-11 * H.cwiseAbs().maxCoeff())
          << "Hessian " << l << "," << j;
  }
}

TEST_P(EmgLikelihoodLaw, GradientAndHessianMatchFiniteDifferences) { check_derivatives(GetParam(), false); }

TEST_P(EmgLikelihoodLaw, GradientAndHessianMatchFiniteDifferencesWithPerPointSpread) {
  check_derivatives(GetParam(), true);
}

TEST_P(EmgLikelihoodLaw, ScaledLikelihoodIsPhysicalLikelihoodUpToJacobian) {
  const DampingKind kind = GetParam();
  const auto pts = emg_points(law_of(kind), 200, 11);
  const ms::EmgProblem pr = ms::make_emg_problem(pts, kind);
  const int k = ms::law_param_count(kind);
  ms::EmgVector theta(k + 2);
  theta.head(k) = ms::scaled_from_law(pr, law_of(kind));
  theta[k] = std::log(0.01);
  theta[k + 1] = std::log(3.0);
  const DampingLaw back = ms::law_from_scaled(pr, theta);
  EXPECT_NEAR(back.alpha1, law_of(kind).alpha1, 1e-12);
  EXPECT_NEAR(back.alpha2, law_of(kind).alpha2, 1e-12 * law_of(kind).alpha2);
  EXPECT_NEAR(back.alpha3, law_of(kind).alpha3, 1e-12);
  const double scaled = ms::emg_loglik_scaled(pr, theta, nullptr, nullptr);
  const double physical = ms::emg_log_likelihood(pts, back, 0.01 * pr.c_scale, 3.0 / pr.c_scale);
  EXPECT_NEAR(scaled - double(pts.size()) * std::log(pr.c_scale), physical, 1e-9 * std::abs(physical));
}

INSTANTIATE_TEST_SUITE_P(Laws, EmgLikelihoodLaw,
                         ::testing::Values(DampingKind::rayleigh, DampingKind::powerlaw, DampingKind::hybrid),
                         [](const auto& info) { return ms::to_string(info.param); });

TEST(EmgLikelihood, PaperRayleighGradientWithMisprintFixed) {
  const DampingLaw law = law_of(DampingKind::rayleigh);
  const auto pts = emg_points(law, 150, 3);
  const double sigma = 0.7, eta = 0.4, n = double(pts.size());
  // Eqs. 1.11-1.15 as printed, except d/dsigma uses n eta^2 sigma.
  double d_eta = n / eta + n * eta * sigma * sigma, d_sigma = n * eta * eta * sigma;
  double d_a1 = eta * n, d_a2 = 0.0;
  for (const auto& p : pts) {
    const double model = ms::damping_c_per_s(law, p.lambda_rad2_s2);
    const double s = (model + eta * sigma * sigma - p.c_per_s) / (std::sqrt(2.0) * sigma);
    const double t = -2.0 / (ms::erfcx(s) * std::sqrt(std::numbers::pi));
    d_eta += model - p.c_per_s + t * sigma / std::sqrt(2.0);
    d_sigma += t * (eta * sigma * sigma + p.c_per_s - model) / (std::sqrt(2.0) * sigma * sigma);
    d_a1 += t / (std::sqrt(2.0) * sigma);
    d_a2 += eta * p.lambda_rad2_s2 + t * p.lambda_rad2_s2 / (std::sqrt(2.0) * sigma);
  }
  auto ll = [&](double a1, double a2, double sg, double et) {
    DampingLaw l = law;
    l.alpha1 = a1;
    l.alpha2 = a2;
    return ms::emg_log_likelihood(pts, l, sg, et);
  };
  const double h = 1e-6;  // relative steps
  const double a1 = law.alpha1, a2 = law.alpha2;
  const double fd_eta = (ll(a1, a2, sigma, eta * (1 + h)) - ll(a1, a2, sigma, eta * (1 - h))) / (2 * h * eta);
  const double fd_sigma = (ll(a1, a2, sigma * (1 + h), eta) - ll(a1, a2, sigma * (1 - h), eta)) / (2 * h * sigma);
  const double fd_a1 = (ll(a1 * (1 + h), a2, sigma, eta) - ll(a1 * (1 - h), a2, sigma, eta)) / (2 * h * a1);
  const double fd_a2 = (ll(a1, a2 * (1 + h), sigma, eta) - ll(a1, a2 * (1 - h), sigma, eta)) / (2 * h * a2);
  EXPECT_NEAR(d_eta, fd_eta, 1e-5 * std::abs(fd_eta));
  EXPECT_NEAR(d_sigma, fd_sigma, 1e-5 * std::abs(fd_sigma));
  EXPECT_NEAR(d_a1, fd_a1, 1e-5 * std::abs(fd_a1));
  EXPECT_NEAR(d_a2, fd_a2, 1e-5 * std::abs(fd_a2));
  // The misprinted n lambda^2 sigma (any lambda of the data) is far off: the fix matters.
  const double misprint = d_sigma - n * eta * eta * sigma + n * std::pow(pts[0].lambda_rad2_s2, 2) * sigma;
  EXPECT_GT(std::abs(misprint - fd_sigma), 1e3 * std::abs(fd_sigma));
}

TEST(EmgLikelihood, FiniteWhenSigmaIsTinyAndPointsFarBelowTheCurve) {
  DampingLaw law = law_of(DampingKind::rayleigh);
  const std::vector<DampingPoint> pts = {{1e6, 2.0}, {1e8, 9.0}, {1e9, 1.0}};  // last: s ~ 1e5
  const double ll = ms::emg_log_likelihood(pts, law, 1e-4, 1.0);
  EXPECT_TRUE(std::isfinite(ll));
  EXPECT_LT(ll, -1e9);  // the Gaussian tail: ~ -(69 - 1)^2 / (2 sigma^2)
}

}  // namespace
