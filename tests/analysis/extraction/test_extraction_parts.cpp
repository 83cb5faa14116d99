// Building blocks of feature extraction: closed-form weighted geometric sums, ESPRIT on exact data,
// noise floor, onset, input checks, and two modes 2 Hz apart resolved by the full pipeline.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include "analysis/extraction/damped_fit.hpp"
#include "analysis/extraction/esprit.hpp"
#include "analysis/extraction/feature_extraction.hpp"
#include "analysis/extraction/noise_floor.hpp"
#include "analysis/extraction/onset.hpp"
#include "extraction_fixtures.hpp"

namespace ms {
namespace {

using cd = std::complex<double>;
constexpr double kFs = 44100.0;

TEST(FeatureDampedFit, WeightedGeometricSumsMatchDirectSums) {
  const std::size_t N = 5000;
  // Small, moderate and aliased (|Im| > pi) exponents, both branches of the implementation.
  for (cd sigma : {cd(-1e-7, 2e-6), cd(-2e-4, 0.03), cd(-0.01, 3.5), cd(0.0, 0.0), cd(-3e-6, -1e-5)}) {
    for (int p = 0; p < 3; ++p) {
      cd direct = 0.0;
      for (std::size_t n = 0; n < N; ++n) direct += std::pow(double(n), p) * std::exp(sigma * double(n));
      const cd closed = weighted_geometric_sum(p, sigma, N);
      EXPECT_LT(std::abs(closed - direct), 1e-9 * std::max(1.0, std::abs(direct))) << sigma << " p=" << p;
    }
  }
}

TEST(FeatureDampedFit, RefineRecoversPolesFromRoughStart) {
  ModalModel m;
  m.modes = {{440.0, 4.0, 0.3, 0.0}, {1234.5, 60.0, 0.1, 0.0}};
  const auto x = render_reference(m, {}, kFs, 22050);
  std::vector<DampedComponent> c;
  for (const auto& mode : m.modes)  // 0.2 % off in frequency, 20 % off in decay
    c.push_back({cd(-1.2 * mode.decay_per_s, 2.0 * std::numbers::pi * mode.freq_hz * 1.002) / kFs, 0.0});
  refine_poles(x, c, {20, 1e-14});
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(c[k].s.imag() * kFs / (2 * std::numbers::pi), m.modes[k].freq_hz, 1e-6);
    EXPECT_NEAR(-c[k].s.real() * kFs, m.modes[k].decay_per_s, 1e-6);
    EXPECT_NEAR(std::abs(c[k].b), m.modes[k].amp, 1e-8);
  }
}

TEST(Esprit, ExactPolesOfNoiselessData) {
  const std::vector<cd> z = {std::polar(0.999, 0.3), std::polar(0.99, -1.1), std::polar(0.98, 0.32)};
  std::vector<cd> y(400);
  for (std::size_t n = 0; n < y.size(); ++n)
    for (std::size_t k = 0; k < z.size(); ++k) y[n] += double(k + 1) * std::pow(z[k], double(n));
  EspritOptions o;
  o.window = 40;
  o.noise_power = 1e-12;  // above round-off, far below the signal
  const auto poles = esprit(y.data(), y.size(), o);
  ASSERT_EQ(poles.size(), 3u);
  for (const cd& t : z) {
    double best = 1.0;
    for (const cd& p : poles) best = std::min(best, std::abs(p - t));
    EXPECT_LT(best, 1e-9);
  }
}

TEST(NoiseFloor, MedianPeriodogramFindsWhiteNoiseUnderAnImpact) {
  double sigma = 0.0;
  const auto x = testing::render_noisy(testing::random_impact(3), kFs, 2.0, 40.0, 3, 0, &sigma);
  const std::vector<double> xd(x.begin(), x.end());
  EXPECT_NEAR(estimate_noise_sigma(xd) / sigma, 1.0, 0.05);
  EXPECT_NEAR(noise_floor_db(0.001), -60.0, 1e-12);
}

TEST(Onset, FindsTheImpactAfterLeadingNoise) {
  for (std::uint64_t seed : {4u, 5u, 6u}) {
    const std::size_t lead = 13000 + 977 * std::size_t(seed);
    const auto x = testing::render_noisy(testing::random_impact(seed), kFs, 1.0, 40.0, seed, lead);
    const std::vector<double> xd(x.begin(), x.end());
    const std::size_t onset = find_onset(xd, estimate_noise_sigma(xd));
    EXPECT_LE(std::abs(double(onset) - double(lead)), 0.0005 * kFs) << seed;  // within 0.5 ms
    const auto f = extract_features(x, kFs);
    EXPECT_NEAR(f.onset_s, double(lead) / kFs, 0.0005);
  }
}

TEST(ExtractInputCheck, NamesSilenceClippingAndShortness) {
  EXPECT_NE(recording_problem(std::vector<float>(44100, 0.0f), kFs)->find("silent"), std::string::npos);
  std::vector<float> square(44100);
  for (std::size_t n = 0; n < square.size(); ++n) square[n] = (n / 40) % 2 ? 1.0f : -1.0f;
  EXPECT_NE(recording_problem(square, kFs)->find("clipped"), std::string::npos);
  EXPECT_NE(recording_problem(std::vector<float>(2000, 0.1f), kFs)->find("too short"), std::string::npos);
  // A normal impact, peak-normalised to full scale, and a 20 Hz sine at full scale are fine.
  auto x = testing::render_noisy(testing::random_impact(9), kFs, 1.0, 40.0, 9);
  float peak = 0.0f;
  for (float v : x) peak = std::max(peak, std::abs(v));
  for (float& v : x) v /= peak;
  EXPECT_FALSE(recording_problem(x, kFs).has_value());
  std::vector<float> sine(44100);
  for (std::size_t n = 0; n < sine.size(); ++n) sine[n] = float(std::sin(2 * std::numbers::pi * 20.0 * double(n) / kFs));
  EXPECT_FALSE(recording_problem(sine, kFs).has_value());
}

TEST(FeatureExtraction, ResolvesModesTwoHertzApart) {
  for (std::uint64_t seed : {11u, 12u, 13u}) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> decay(0.5, 5.0), gain(0.5, 1.0);
    ModalModel m;
    m.modes = {{440.0, decay(rng), 0.3 * gain(rng), 0.0}, {442.0, decay(rng), 0.3 * gain(rng), 0.0}};
    const auto x = testing::render_noisy(m, kFs, 2.0, 40.0, seed);
    const auto f = extract_features(x, kFs);
    ASSERT_EQ(f.modes.size(), 2u) << seed;
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_NEAR(f.modes[k].freq_hz, m.modes[k].freq_hz, 0.01) << seed;
      EXPECT_NEAR(f.modes[k].decay_per_s / m.modes[k].decay_per_s, 1.0, 0.03) << seed;
      EXPECT_NEAR(f.modes[k].amp / m.modes[k].amp, 1.0, 0.03) << seed;
    }
  }
}

TEST(FeatureExtraction, DropsStationaryHum) {
  ModalModel m;
  m.modes = {{50.0, 0.0, 0.05, 0.0}, {660.0, 8.0, 0.4, 0.0}};  // mains hum + one mode
  const auto x = testing::render_noisy(m, kFs, 2.0, 40.0, 21);
  const auto f = extract_features(x, kFs);
  ASSERT_EQ(f.modes.size(), 1u);
  EXPECT_NEAR(f.modes[0].freq_hz, 660.0, 0.01);
}

}  // namespace
}  // namespace ms
