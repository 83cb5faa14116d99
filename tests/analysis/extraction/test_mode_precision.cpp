// The Cramer-Rao bounds of mode_precision against Monte-Carlo: many noisy copies of known modes,
// each fitted by maximum likelihood (refine_poles from the truth); the spread of the estimates must
// be what the bound says (an ML fit of damped sinusoids at high SNR is efficient).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "analysis/extraction/damped_fit.hpp"
#include "analysis/extraction/mode_precision.hpp"

namespace ms {
namespace {

using cd = std::complex<double>;
constexpr double kFs = 44100.0;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

DampedComponent mode(double freq_hz, double decay_per_s, double amp) {
  return {cd(-decay_per_s, kTwoPi * freq_hz) / kFs, cd(0.0, -amp)};
}

struct Spread {
  std::vector<double> freq_sd, decay_sd, amp_sd;  // per mode, over the trials
};

// Standard deviations of the ML estimates over `trials` noisy renderings; amplitudes at -offset.
Spread monte_carlo(const std::vector<DampedComponent>& truth, std::size_t frames, double sigma, int trials,
                   double offset = 0.0) {
  const std::vector<double> clean = [&] {
    std::vector<double> zeros(frames, 0.0), y = subtract_components(zeros, truth, frames);
    for (double& v : y) v = -v;
    return y;
  }();
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, sigma);
  const std::size_t K = truth.size();
  std::vector<double> sf(K), sd(K), sa(K);
  RefineOptions ro;
  ro.max_iterations = 30;
  ro.relative_tolerance = 1e-12;
  for (int t = 0; t < trials; ++t) {
    std::vector<double> x = clean;
    for (double& v : x) v += noise(rng);
    std::vector<DampedComponent> fit = truth;
    refine_poles(x, fit, ro);
    for (std::size_t k = 0; k < K; ++k) {
      const double ef = (fit[k].s.imag() - truth[k].s.imag()) * kFs / kTwoPi;
      const double ed = (fit[k].s.real() - truth[k].s.real()) * kFs;
      const double ea = std::abs(fit[k].b * std::exp(-fit[k].s * offset)) -
                        std::abs(truth[k].b * std::exp(-truth[k].s * offset));
      sf[k] += ef * ef;
      sd[k] += ed * ed;
      sa[k] += ea * ea;
    }
  }
  Spread s;
  for (std::size_t k = 0; k < K; ++k) {
    s.freq_sd.push_back(std::sqrt(sf[k] / trials));
    s.decay_sd.push_back(std::sqrt(sd[k] / trials));
    s.amp_sd.push_back(std::sqrt(sa[k] / trials));
  }
  return s;
}

// 400 trials: the sample standard deviation is within ~7 % of its true value (2 standard errors).
constexpr int kTrials = 400;
constexpr double kTolerance = 0.12;

TEST(ModePrecision, OneModeMatchesMonteCarlo) {
  const std::vector<DampedComponent> truth{mode(440.0, 25.0, 0.3)};
  const std::size_t frames = 11025;
  const double sigma = 0.02;
  const auto bound = mode_precision(truth, frames, kFs, sigma);
  const Spread mc = monte_carlo(truth, frames, sigma, kTrials);
  EXPECT_NEAR(mc.freq_sd[0] / bound[0].freq_sd_hz, 1.0, kTolerance);
  EXPECT_NEAR(mc.decay_sd[0] / bound[0].decay_sd_per_s, 1.0, kTolerance);
  EXPECT_NEAR(mc.amp_sd[0] / bound[0].amp_sd, 1.0, kTolerance);
  // The single-mode bound in closed form (continuous-time limit, record long against 1/d, f >> d):
  // var(omega) = var(d) = 16 d^3 sigma^2 / (a^2 fs).
  const double sd_closed = 4.0 * std::pow(25.0, 1.5) * sigma / (0.3 * std::sqrt(kFs));
  EXPECT_NEAR(bound[0].freq_sd_hz * kTwoPi / sd_closed, 1.0, 0.01);
  EXPECT_NEAR(bound[0].decay_sd_per_s / sd_closed, 1.0, 0.01);
  std::printf("one mode: freq sd %.4g Hz (Monte-Carlo %.4g), decay sd %.4g 1/s (%.4g), amp sd %.4g (%.4g)\n",
              bound[0].freq_sd_hz, mc.freq_sd[0], bound[0].decay_sd_per_s, mc.decay_sd[0], bound[0].amp_sd,
              mc.amp_sd[0]);
}

TEST(ModePrecision, OverlappingModesAreLessPreciseAndStillMatchMonteCarlo) {
  // Two modes 6 Hz apart, each decaying at 30-40 1/s: their Lorentzians overlap.
  const std::vector<DampedComponent> truth{mode(440.0, 30.0, 0.3), mode(446.0, 40.0, 0.2)};
  const std::size_t frames = 22050;
  const double sigma = 0.005;
  const auto joint = mode_precision(truth, frames, kFs, sigma);
  const auto alone = mode_precision({truth[0]}, frames, kFs, sigma);
  EXPECT_GT(joint[0].freq_sd_hz, 1.5 * alone[0].freq_sd_hz);  // the neighbour costs precision
  const Spread mc = monte_carlo(truth, frames, sigma, kTrials);
  std::printf("pair: freq sd %.4g / %.4g Hz (Monte-Carlo %.4g / %.4g), alone %.4g\n", joint[0].freq_sd_hz,
              joint[1].freq_sd_hz, mc.freq_sd[0], mc.freq_sd[1], alone[0].freq_sd_hz);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(mc.freq_sd[k] / joint[k].freq_sd_hz, 1.0, kTolerance) << k;
    EXPECT_NEAR(mc.decay_sd[k] / joint[k].decay_sd_per_s, 1.0, kTolerance) << k;
    EXPECT_NEAR(mc.amp_sd[k] / joint[k].amp_sd, 1.0, kTolerance) << k;
  }
}

TEST(ModePrecision, AmplitudeAtTheOnsetCarriesTheDecayUncertainty) {
  // The extraction reports amplitudes 2 ms before the fit's first sample (a skipped contact).
  const std::vector<DampedComponent> truth{mode(1200.0, 150.0, 0.4)};
  const std::size_t frames = 8820;
  const double sigma = 0.01, offset = 0.002 * kFs;
  const auto at_start = mode_precision(truth, frames, kFs, sigma);
  const auto at_onset = mode_precision(truth, frames, kFs, sigma, offset);
  EXPECT_GT(at_onset[0].amp_sd, at_start[0].amp_sd);
  EXPECT_DOUBLE_EQ(at_onset[0].freq_sd_hz, at_start[0].freq_sd_hz);
  const Spread mc = monte_carlo(truth, frames, sigma, kTrials, offset);
  EXPECT_NEAR(mc.amp_sd[0] / at_onset[0].amp_sd, 1.0, kTolerance);
}

// The closed-form Gram is J^T J of the Jacobian evaluated sample by sample.
TEST(ModePrecision, GramIsTheJacobiansGram) {
  const std::vector<DampedComponent> c{mode(180.0, 40.0, 0.3), mode(215.0, 300.0, 0.1), mode(3000.0, 2.0, 0.05)};
  const std::size_t frames = 3000;
  Eigen::MatrixXd J(Eigen::Index(frames), 12);
  for (std::size_t k = 0; k < c.size(); ++k)
    for (std::size_t n = 0; n < frames; ++n) {
      const cd e = std::exp(c[k].s * double(n)), be = c[k].b * e * double(n);
      const auto row = Eigen::Index(n), col = Eigen::Index(4 * k);
      J(row, col) = e.real();       // d/d Re b of Re(b e^{sn})
      J(row, col + 1) = -e.imag();  // d/d Im b
      J(row, col + 2) = be.real();  // d/d Re s
      J(row, col + 3) = -be.imag(); // d/d Im s
    }
  const Eigen::MatrixXd explicit_gram = J.transpose() * J;
  const Eigen::MatrixXd closed = pole_gram(c, frames);
  for (Eigen::Index i = 0; i < 12; ++i)
    for (Eigen::Index j = 0; j < 12; ++j)
      EXPECT_NEAR(closed(i, j), explicit_gram(i, j),
                  1e-9 * std::sqrt(explicit_gram(i, i) * explicit_gram(j, j)))
          << i << "," << j;
}

TEST(ModePrecision, CoincidentPolesHaveNoFiniteBound) {
  // Two identical poles: the data fix their sum, not how it is shared.
  const std::vector<DampedComponent> twins{mode(300.0, 10.0, 0.2), mode(300.0, 10.0, 0.2),
                                           mode(900.0, 10.0, 0.2)};
  const auto p = mode_precision(twins, 4410, kFs, 0.01);
  EXPECT_TRUE(std::isinf(p[0].freq_sd_hz));
  EXPECT_TRUE(std::isinf(p[1].amp_sd));
  // A well separated third mode keeps its finite bound.
  EXPECT_TRUE(std::isfinite(p[2].freq_sd_hz));
  EXPECT_LT(p[2].freq_sd_hz, 1.0);
  EXPECT_TRUE(mode_precision({}, 100, kFs, 0.01).empty());
}

}  // namespace
}  // namespace ms
