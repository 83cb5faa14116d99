// A strike's mode amplitudes read with the poles held fixed: exact on the modes alone, and beside a
// room's fast pair in near antiphase (which the free fit can take for the mode) still the mode's.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace ms::audit
