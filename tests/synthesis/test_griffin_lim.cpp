// Griffin-Lim on the residual's grid: from the power of a real sound it finds a signal whose
// spectrogram lies within -20 dB (spectral convergence) in the default 100 iterations, one seed gives
// the same samples every time, and the momentum of the fast variant is what gets it there.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "synthesis/griffin_lim.hpp"

using namespace ms;

namespace {

constexpr double kFs = 44100.0;

// A residual-like sound: a noise burst at the strike decaying at 60 1/s, and two damped partials.
std::vector<float> test_sound(std::size_t samples, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<float> x(samples);
  for (std::size_t n = 0; n < samples; ++n) {
    const double t = double(n) / kFs;
    x[n] = float(0.3 * normal(rng) * std::exp(-60.0 * t) + 0.2 * std::exp(-8.0 * t) * std::sin(2 * std::numbers::pi * 523.0 * t) +
                 0.1 * std::exp(-20.0 * t) * std::sin(2 * std::numbers::pi * 3100.0 * t));
  }
  return x;
}

std::vector<float> power_of(const std::vector<float>& x, const StftGrid& grid) {
  Stft stft(grid);
  const std::vector<double> p = stft.power(x);
  return std::vector<float>(p.begin(), p.end());
}

}  // namespace

TEST(GriffinLim, ReachesMinus20dBInTheDefaultIterations) {
  const StftGrid grid;
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const std::vector<float> x = test_sound(22050, 100 + seed);
    const std::vector<float> target = power_of(x, grid);
    GriffinLimOptions options;
    options.seed = seed;
    ASSERT_EQ(options.iterations, 100u);
    const GriffinLimResult r = griffin_lim(target, grid, x.size(), options);
    ASSERT_EQ(r.samples.size(), x.size());
    EXPECT_LE(r.spectral_convergence_db, -20.0) << seed;
    RecordProperty("spectral_convergence_db_seed_" + std::to_string(seed), std::to_string(r.spectral_convergence_db));
    // The reported figure is the returned samples' own.
    EXPECT_NEAR(spectral_convergence_db(r.samples, target, grid), r.spectral_convergence_db, 0.05);
    // Energy is kept: the rebuilt sound is as loud as the original within 0.5 dB.
    double e0 = 0.0, e1 = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      e0 += double(x[i]) * x[i];
      e1 += double(r.samples[i]) * r.samples[i];
    }
    EXPECT_NEAR(10.0 * std::log10(e1 / e0), 0.0, 0.5);
  }
}

TEST(GriffinLim, MomentumConvergesFurtherThanTheOriginal) {
  const StftGrid grid;
  const std::vector<float> x = test_sound(22050, 7);
  const std::vector<float> target = power_of(x, grid);
  GriffinLimOptions original;
  original.momentum = 0.0;
  const double plain = griffin_lim(target, grid, x.size(), original).spectral_convergence_db;
  const double fast = griffin_lim(target, grid, x.size(), {}).spectral_convergence_db;
  EXPECT_LT(fast, plain - 3.0) << "plain " << plain << " dB, fast " << fast << " dB";
  RecordProperty("plain_db", std::to_string(plain));
  RecordProperty("fast_db", std::to_string(fast));
}

TEST(GriffinLim, OneSeedOneSignal) {
  const StftGrid grid;
  const std::vector<float> target = power_of(test_sound(8000, 3), grid);
  GriffinLimOptions a;
  a.seed = 42;
  a.iterations = 20;
  const GriffinLimResult first = griffin_lim(target, grid, 8000, a), again = griffin_lim(target, grid, 8000, a);
  EXPECT_EQ(first.samples, again.samples);
  GriffinLimOptions b = a;
  b.seed = 43;
  EXPECT_NE(griffin_lim(target, grid, 8000, b).samples, first.samples);
}

TEST(GriffinLim, SilenceAndWrongSizes) {
  const StftGrid grid;
  const std::size_t samples = 3000;
  const GriffinLimResult silent = griffin_lim(std::vector<float>(grid.frames_for(samples) * grid.bins(), 0.0f), grid, samples);
  for (float v : silent.samples) ASSERT_EQ(v, 0.0f);
  EXPECT_TRUE(std::isinf(silent.spectral_convergence_db) && silent.spectral_convergence_db < 0);
  EXPECT_THROW(griffin_lim(std::vector<float>(10, 1.0f), grid, samples), std::invalid_argument);
  std::vector<float> negative(grid.frames_for(samples) * grid.bins(), 1.0f);
  negative[7] = -1.0f;
  EXPECT_THROW(griffin_lim(negative, grid, samples), std::invalid_argument);
}
