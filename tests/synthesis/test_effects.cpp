// Effects: support damping (one-sided excess decay) and split doublets (beating).
#include <gtest/gtest.h>

#include <cmath>

#include "synthesis/effects.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/reference_renderer.hpp"

using namespace ms;

namespace {
ModalModel flat(std::size_t n) {
  ModalModel m;
  for (std::size_t i = 0; i < n; ++i) m.modes.push_back(Mode{100.0 + i, 2.0, 1.0, 0.0});
  return m;
}
}  // namespace

TEST(SupportDamping, ConstantPerModeAndExponentialExcess) {
  ModalModel m = flat(3);
  apply_support_damping(m, SupportDamping{0.5, {1.0, 0.0, 2.0}, 0.0, 0});
  EXPECT_DOUBLE_EQ(m.modes[0].decay_per_s, 3.5);
  EXPECT_DOUBLE_EQ(m.modes[1].decay_per_s, 2.5);
  EXPECT_DOUBLE_EQ(m.modes[2].decay_per_s, 4.5);
  // Exponential excess: non-negative, mean as asked, reproducible for a seed.
  ModalModel a = flat(20000), b = flat(20000);
  apply_support_damping(a, SupportDamping{0.0, {}, 3.0, 17});
  apply_support_damping(b, SupportDamping{0.0, {}, 3.0, 17});
  double sum = 0;
  for (std::size_t i = 0; i < a.modes.size(); ++i) {
    const double excess = a.modes[i].decay_per_s - 2.0;
    ASSERT_GE(excess, 0.0);
    ASSERT_EQ(a.modes[i].decay_per_s, b.modes[i].decay_per_s);
    sum += excess;
  }
  EXPECT_NEAR(sum / 20000, 3.0, 0.1);  // standard error 3/sqrt(20000) = 0.02
}

TEST(Doublets, SplitAndBeat) {
  ModalModel m;
  m.modes.push_back(Mode{1000.0, 1.0, 1.0, 0.0});
  apply_doublets(m, Doublets{0.0, 2.0, 0.5, 1}, {});
  ASSERT_EQ(m.modes.size(), 2u);
  EXPECT_DOUBLE_EQ(m.modes[0].freq_hz, 999.0);
  EXPECT_DOUBLE_EQ(m.modes[1].freq_hz, 1001.0);
  EXPECT_DOUBLE_EQ(m.modes[0].amp + m.modes[1].amp, 1.0);
  // Equal halves beat with period 1/2 Hz = 0.5 s: the envelope vanishes at t = 0.25 s.
  const auto y = render_reference(m, Excitation{}, 8000.0, 8000);
  double near_null = 0, near_peak = 0;
  for (int n = 1980; n < 2020; ++n) near_null = std::max(near_null, std::abs(y[std::size_t(n)]));
  for (int n = 3980; n < 4020; ++n) near_peak = std::max(near_peak, std::abs(y[std::size_t(n)]));
  EXPECT_LT(near_null, 0.03);
  EXPECT_GT(near_peak, 0.5);
}

TEST(Doublets, PlateSplitsOnlyNonAxisymmetricModes) {
  const std::string base = R"(duration_s: 1
object: {type: plate, radius_m: 0.1, thickness_m: 0.003, max_modes: 20}
material: sterling2019/glass
)";
  const ParamSet plain = parse_paramset(base, "p.yaml", ".");
  const ParamSet split = parse_paramset(base + "effects: {doublets: {split_rel: 0.001}}\n", "p.yaml", ".");
  // The first 20 plate modes include axisymmetric ones (0 nodal diameters), which stay single.
  EXPECT_GT(split.model.modes.size(), plain.model.modes.size());
  EXPECT_LT(split.model.modes.size(), 2 * plain.model.modes.size());
  EXPECT_NEAR(split.model.modes[1].freq_hz - split.model.modes[0].freq_hz, 0.001 * plain.model.modes[0].freq_hz,
              1e-9);
}

TEST(BackgroundNoise, SnrIsAsAskedAndSeeded) {
  std::vector<float> y(44100);
  for (std::size_t n = 0; n < y.size(); ++n) y[n] = float(0.5 * std::sin(2 * M_PI * 440.0 * n / 44100.0));
  std::vector<float> a = y, b = y;
  add_background_noise(a, BackgroundNoise{30.0, 9, true});
  add_background_noise(b, BackgroundNoise{30.0, 9, true});
  EXPECT_EQ(a, b);
  double signal = 0, noise = 0;
  for (std::size_t n = 0; n < y.size(); ++n) {
    signal += double(y[n]) * y[n];
    noise += double(a[n] - y[n]) * (a[n] - y[n]);
  }
  EXPECT_NEAR(10 * std::log10(signal / noise), 30.0, 0.1);  // 44100 draws: sd of the estimate ~0.03 dB
  const ParamSet p = parse_paramset("duration_s: 1\nmodes: [{freq_hz: 440, decay_per_s: 1, amp: 1}]\n"
                                    "effects: {noise: {snr_db: 40, seed: 3}}\n", "n.yaml", ".");
  EXPECT_TRUE(p.noise.enabled);
  EXPECT_EQ(p.noise.snr_db, 40.0);
}
