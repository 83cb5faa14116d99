// A strike's mode amplitudes read with the poles held fixed: exact on the modes alone, beside a room's
// fast pair in near antiphase (which the free fit can take for the mode) still the mode's, and a doublet too
// close to beat apart read steadily as one pole.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "analysis/audit/fixed_pole_amplitudes.hpp"

namespace ms::audit {
namespace {

constexpr double kRateHz = 44100.0;

std::vector<float> render(const std::vector<Mode>& modes, double seconds) {
  std::vector<float> x(std::size_t(seconds * kRateHz), 0.0f);
  for (std::size_t n = 0; n < x.size(); ++n) {
    const double t = double(n) / kRateHz;
    double v = 0.0;
    for (const Mode& m : modes) v += m.amp * std::exp(-m.decay_per_s * t) * std::sin(2.0 * std::numbers::pi * m.freq_hz * t + m.phase_rad);
    x[n] = float(v);
  }
  return x;
}

TEST(FixedPoleAmplitudes, ModesAloneAreReadAtTheirAmplitudesAtTheFirstSample) {
  const std::vector<Mode> modes{{220.0, 3.0, 0.5, 0.3}, {531.0, 6.0, 0.2, 1.1}, {1207.5, 14.0, 0.05, -0.4}};
  const std::vector<double> amp = fixed_pole_amplitudes(render(modes, 1.0), kRateHz, modes, 0.002);
  ASSERT_EQ(amp.size(), modes.size());
  // float samples: the fit is exact to their rounding
  for (std::size_t k = 0; k < modes.size(); ++k) EXPECT_NEAR(amp[k], modes[k].amp, 1e-6 * modes[k].amp + 1e-7) << k;
}

TEST(FixedPoleAmplitudes, ARoomsFastPairBesideAModeLeavesTheModesAmplitude) {
  // A slow mode, and beside it two fast components four times as loud in near antiphase with a little
  // decaying noise: together nearly silent after their first tens of milliseconds.
  const Mode mode{798.0, 3.2, 0.24, 0.0};
  std::vector<Mode> heard{mode, {798.5, 22.0, 0.96, 0.0}, {798.8, 26.0, 0.96, std::numbers::pi - 0.05}};
  std::vector<float> x = render(heard, 1.0);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1e-3);
  for (std::size_t n = 0; n < x.size(); ++n) x[n] += float(noise(rng) * std::exp(-10.0 * double(n) / kRateHz));
  const std::vector<double> amp = fixed_pole_amplitudes(x, kRateHz, {mode}, 0.002);
  ASSERT_EQ(amp.size(), 1u);
  // Either member alone is 12 dB louder than the mode; what their imbalance projects onto the mode's
  // pole moves it by 1.2 dB, the same in every strike that differs by a gain (the fit is linear).
  EXPECT_NEAR(std::log(amp[0] / mode.amp), 0.0, 0.2);
}

TEST(FixedPoleAmplitudes, NoPolesOrNoSamplesReadNothing) {
  EXPECT_TRUE(fixed_pole_amplitudes(std::vector<float>(100, 0.1f), kRateHz, {}, 0.002).empty());
  const std::vector<double> amp = fixed_pole_amplitudes({}, kRateHz, {{440.0, 5.0, 1.0, 0.0}}, 0.002);
  ASSERT_EQ(amp.size(), 1u);
  EXPECT_EQ(amp[0], 0.0);
}

TEST(FixedPoleAmplitudes, APairTooCloseToBeatApartIsReadSteadilyAsOnePole) {
  // Two members 0.06 Hz apart, decaying at 2/s, drift 0.19 rad apart in the half second they are heard:
  // as two poles their columns are all but one, and what else sounds near them decides how the fit
  // splits the pair. Here, a room's answer around the pair, different in every strike: four fast
  // components within 3 Hz of it, each 20 dB below it.
  const Mode lo{999.97, 2.0, 0.3, 0.4}, hi{1000.03, 2.0, 0.2, 0.4};
  ASSERT_FALSE(pair_beats_apart(hi.freq_hz - lo.freq_hz, lo.decay_per_s, 1.0));
  const Mode centre{1000.0, 2.0, lo.amp + hi.amp, 0.4};
  const std::vector<float> pair = render({lo, hi}, 1.0);
  std::vector<double> as_two_db, as_one_db;
  for (unsigned strike = 1; strike <= 8; ++strike) {
    std::mt19937_64 rng(strike);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Mode> room;
    for (int k = 0; k < 4; ++k) room.push_back({1000.0 + 6.0 * (u(rng) - 0.5), 20.0, 0.05, 2.0 * std::numbers::pi * u(rng)});
    std::vector<float> x = render(room, 1.0);
    for (std::size_t n = 0; n < x.size(); ++n) x[n] += pair[n];
    const std::vector<double> two = fixed_pole_amplitudes(x, kRateHz, {lo, hi}, 0.002);
    const std::vector<double> one = fixed_pole_amplitudes(x, kRateHz, {centre}, 0.002);
    as_two_db.push_back(20.0 * std::log10(std::hypot(two[0], two[1]) / std::hypot(lo.amp, hi.amp)));
    as_one_db.push_back(20.0 * std::log10(one[0] / centre.amp));
  }
  const auto spread_db = [](const std::vector<double>& v) {
    return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  };
  // Measured: 5.1 dB over the eight strikes as two poles (five read 2.9-5.0 dB loud), 0.64 dB as one.
  EXPECT_GT(spread_db(as_two_db), 3.0);
  EXPECT_LT(spread_db(as_one_db), 1.0);
}

TEST(FixedPoleAmplitudes, PairsBeatApartWhenTheirPhasesDriftARadianWhileHeard) {
  EXPECT_TRUE(pair_beats_apart(1.5, 3.0, 1.0));    // the generators' narrowest doublet: 3.1 rad in 1/3 s
  EXPECT_FALSE(pair_beats_apart(0.1, 3.0, 1.0));   // 0.21 rad before it has decayed by a neper
  EXPECT_FALSE(pair_beats_apart(0.1, 0.0, 1.0));   // undamped, 0.63 rad over the second heard
  EXPECT_TRUE(pair_beats_apart(0.2, 0.0, 1.0));    // 1.26 rad
  EXPECT_FALSE(pair_beats_apart(0.5, 0.5, 0.25));  // heard for a quarter second only: 0.79 rad
}

}  // namespace
}  // namespace ms::audit
