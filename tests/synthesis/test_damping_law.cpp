// Damping laws and eigenvalue -> mode conversion against the closed forms of DESIGN.md §3.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "synthesis/damping_law.hpp"
#include "synthesis/material.hpp"

using namespace ms;

TEST(DampingLaw, RayleighIsExactFormula) {
  const DampingLaw law{DampingKind::rayleigh, 6.3035, 2.1160e-8, 1.0, 0.0};  // Ren metal
  for (double lambda : {1e4, 1e7, 4e9}) EXPECT_DOUBLE_EQ(law.decay_per_s(lambda), 0.5 * (6.3035 + 2.1160e-8 * lambda));
}

TEST(DampingLaw, ModesLieOnRayleighCircle) {
  // omega^2 + (d - 1/beta)^2 = (1 - alpha beta) / beta^2 (Ren 2014, eq. 3.8).
  const double alpha = 18.301, beta = 1.4342e-7;  // Ren glass
  const DampingLaw law{DampingKind::rayleigh, alpha, beta, 1.0, 0.0};
  std::vector<double> lambda;
  for (int i = 1; i <= 50; ++i) lambda.push_back(std::pow(2 * std::numbers::pi * 100.0 * i, 2));
  std::size_t overdamped = 99;
  const ModalModel m = modes_from_eigenvalues(lambda, law, 1.0, 1.0, {}, &overdamped);
  EXPECT_EQ(overdamped, 0u);
  ASSERT_EQ(m.modes.size(), lambda.size());
  const double r2 = (1 - alpha * beta) / (beta * beta);
  for (const Mode& mode : m.modes) {
    const double w = 2 * std::numbers::pi * mode.freq_hz;
    EXPECT_NEAR((w * w + std::pow(mode.decay_per_s - 1 / beta, 2)) / r2, 1.0, 1e-12);
  }
}

TEST(DampingLaw, FrequencyFromEigenvalue) {
  const DampingLaw law{DampingKind::rayleigh, 2.0, 7.8e-8, 1.0, 0.0};
  const double lambda = std::pow(2 * std::numbers::pi * 1000.0, 2);
  const ModalModel m = modes_from_eigenvalues({lambda}, law, 1.0, 1.0, {}, nullptr);
  const double d = 0.5 * (2.0 + 7.8e-8 * lambda);
  EXPECT_DOUBLE_EQ(m.modes[0].decay_per_s, d);
  EXPECT_DOUBLE_EQ(m.modes[0].freq_hz, std::sqrt(lambda - d * d) / (2 * std::numbers::pi));
}

TEST(DampingLaw, OverdampedModesAreDroppedAndCounted) {
  const DampingLaw law{DampingKind::rayleigh, 0.0, 1e-3, 1.0, 0.0};  // d = lambda/2000
  // lambda = 1e6: d = 500, d^2 = 2.5e5 < 1e6 (kept); lambda = 1e7: d = 5000, d^2 = 2.5e7 > 1e7 (dropped)
  std::size_t overdamped = 0;
  const ModalModel m = modes_from_eigenvalues({1e6, 1e7, 4e6}, law, 1.0, 1.0, {}, &overdamped);
  EXPECT_EQ(overdamped, 2u);  // 4e6: d = 2000, d^2 = 4e6 -> critically damped, dropped
  ASSERT_EQ(m.modes.size(), 1u);
}

TEST(DampingLaw, SterlingWorkedExamplePorcelainAt10kHz) {
  // Sterling et al. 2019, §1.3: "a 10 kHz mode on the porcelain plate has d = 20 with the provided
  // parameters (hybrid alpha3 = 1.027), but alpha3 = 1 reduces it to d = 12" -- holds with lambda = omega^2.
  const Material* porcelain = find_material("sterling2019/porcelain");
  ASSERT_NE(porcelain, nullptr);
  const double lambda = std::pow(2 * std::numbers::pi * 10000.0, 2);
  EXPECT_NEAR(porcelain->hybrid->decay_per_s(lambda), 20.0, 1.0);
  DampingLaw rayleigh_like = *porcelain->hybrid;
  rayleigh_like.alpha3 = 1.0;
  EXPECT_NEAR(rayleigh_like.decay_per_s(lambda), 12.0, 0.5);
}

TEST(DampingLaw, PowerLawHybridAndConstantQ) {
  const double omega = 2 * std::numbers::pi * 440.0, lambda = omega * omega;
  const DampingLaw power{DampingKind::powerlaw, 0.0, 3e-8, 1.05, 0.0};
  EXPECT_NEAR(power.decay_per_s(lambda), 0.5 * 3e-8 * std::pow(omega, 2.1), 1e-12);
  const DampingLaw hybrid{DampingKind::hybrid, 4.0, 3e-8, 1.0, 0.0};
  const DampingLaw rayleigh{DampingKind::rayleigh, 4.0, 3e-8, 1.0, 0.0};
  EXPECT_NEAR(hybrid.decay_per_s(lambda), rayleigh.decay_per_s(lambda), 1e-12);  // alpha3 = 1
  const DampingLaw q{DampingKind::constant_q, 0.0, 0.0, 1.0, 0.01};
  EXPECT_NEAR(q.decay_per_s(lambda), 2 * std::numbers::pi * 440.0 * 0.01, 1e-9);  // d = 2 pi f D
}

TEST(DampingLaw, StiffnessScalingScalesEigenvalues) {
  const DampingLaw law{DampingKind::rayleigh, 0.0, 0.0, 1.0, 0.0};
  const ModalModel a = modes_from_eigenvalues({1e6}, law, 1.0, 1.0, {}, nullptr);
  const ModalModel b = modes_from_eigenvalues({1e6}, law, 4.0, 1.0, {}, nullptr);
  EXPECT_NEAR(b.modes[0].freq_hz / a.modes[0].freq_hz, 2.0, 1e-12);  // f ~ sqrt(gamma)
}

TEST(DampingLaw, NegativeGainBecomesPhase) {
  const DampingLaw law{DampingKind::rayleigh, 1.0, 0.0, 1.0, 0.0};
  const ModalModel m = modes_from_eigenvalues({1e6, 2e6}, law, 1.0, 2.0, {0.5, -0.25}, nullptr);
  EXPECT_DOUBLE_EQ(m.modes[0].amp, 1.0);
  EXPECT_DOUBLE_EQ(m.modes[1].amp, 0.5);
  EXPECT_DOUBLE_EQ(m.modes[1].phase_rad, std::numbers::pi);
}

TEST(DampingLaw, ParseNames) {
  EXPECT_EQ(parse_damping_kind("hybrid"), DampingKind::hybrid);
  EXPECT_THROW(parse_damping_kind("rayleig"), std::invalid_argument);
}

namespace {

DampingLaw relaxation_law(double alpha1, double loss_factor, double strength, double peak_hz) {
  DampingLaw law;
  law.kind = DampingKind::relaxation;
  law.alpha1 = alpha1;
  law.loss_factor = loss_factor;
  law.relaxation_strength = strength;
  law.relaxation_hz = peak_hz;
  return law;
}

}  // namespace

// The relaxation law at hand-computed points: at the peak (f = relaxation_hz, x = 1) the loss factor
// is D + S/2; far below it D alone; far above it the peak's term tends to the constant S omega_r.
TEST(DampingLaw, RelaxationIsConstantLossPlusOneDebyePeak) {
  DampingLaw law = relaxation_law(3.0, 1e-4, 6e-4, 4000.0);
  const auto decay_at = [&](double f) { return law.decay_per_s(std::pow(2 * std::numbers::pi * f, 2)); };
  const double w_peak = 2 * std::numbers::pi * 4000.0;
  EXPECT_NEAR(decay_at(4000.0), 1.5 + w_peak * (1e-4 + 3e-4), 1e-9);
  // f = 2 f_r: x / (1 + x^2) = 2 / 5
  EXPECT_NEAR(decay_at(8000.0), 1.5 + 2 * w_peak * (1e-4 + 6e-4 * 0.4), 1e-9);
  const double w_low = 2 * std::numbers::pi * 10.0;
  // f = f_r / 400: the peak adds S x = 6e-4 / 400 = 1.5e-6 to the loss factor D = 1e-4
  EXPECT_NEAR((decay_at(10.0) - 1.5) / w_low, 1e-4 + 6e-4 * (1.0 / 400) / (1 + 1.0 / 160000), 1e-15);
  EXPECT_NEAR((decay_at(10.0) - 1.5) / w_low / 1e-4, 1.0, 0.02);
  const double w_high = 2 * std::numbers::pi * 4e6;
  EXPECT_NEAR((decay_at(4e6) - 1.5 - w_high * 1e-4) / (6e-4 * w_peak), 1.0, 1e-5);
  law.relaxation_hz = 0.0;  // no peak: constant-Q plus alpha1
  EXPECT_DOUBLE_EQ(decay_at(4000.0), 1.5 + w_peak * 1e-4);
}

// Why the stand-ins use it: over 100 Hz - 12 kHz no hybrid law alpha1 + alpha2 omega^(2 alpha3) (Rayleigh
// and the power law are its special cases) follows a relaxation law with a peak inside the band. The
// best hybrid, by least squares on log decay over a dense grid of alpha3 with alpha1, alpha2 >= 0 solved
// exactly for each (non-negative least squares in two unknowns), still misses by more than 25 % rms
// (32.9 % when measured, at alpha3 = 0.515). The law is the glass stand-in's of
// stimuli/replications/sterling2019/standins/.
TEST(DampingLaw, RelaxationIsOutsideEveryHybridLaw) {
  const DampingLaw law = relaxation_law(1.0, 2e-5, 3e-3, 2000.0);
  std::vector<double> omega, d;
  for (double f = 100.0; f <= 12000.0; f *= 1.05) {
    omega.push_back(2 * std::numbers::pi * f);
    d.push_back(law.decay_per_s(omega.back() * omega.back()));
  }
  double best_rms = 1e300;
  for (double a3 = 0.2; a3 <= 1.6; a3 += 0.005) {
    // Weighted least squares of d ~ a + b omega^(2 a3) with weights 1/d (relative error), a, b >= 0.
    double saa = 0, sab = 0, sbb = 0, sad = 0, sbd = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      const double u = 1.0 / d[i], v = std::pow(omega[i], 2 * a3) / d[i];
      saa += u * u, sab += u * v, sbb += v * v, sad += u, sbd += v;  // target d/d = 1
    }
    std::vector<std::pair<double, double>> candidates;
    const double det = saa * sbb - sab * sab;
    if (det > 0) candidates.emplace_back((sad * sbb - sbd * sab) / det, (sbd * saa - sad * sab) / det);
    candidates.emplace_back(sad / saa, 0.0);
    candidates.emplace_back(0.0, sbd / sbb);
    for (auto [a, b] : candidates) {
      if (a < 0 || b < 0) continue;
      double ss = 0;
      for (std::size_t i = 0; i < d.size(); ++i) {
        const double r = std::log((a + b * std::pow(omega[i], 2 * a3)) / d[i]);
        ss += r * r;
      }
      best_rms = std::min(best_rms, std::sqrt(ss / double(d.size())));
    }
  }
  EXPECT_GT(best_rms, 0.25) << "a hybrid law follows the relaxation law within " << best_rms;
}
