// The band-pass bank against Pd's [bp~] recursion written out here sample by sample from d_filter.c,
// its decay and onset against the closed form of a two-pole resonator, the clipper, streaming, and the
// two Q tables of Skandalou & Ireland (2017).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "synthesis/bandpass_bank.hpp"

using namespace ms;

namespace {

// sigbp_docoef and sigbp_perform of Pd's d_filter.c, transcribed for one filter: t_float and t_sample
// are float, pi is 3.14159, qcos the 6th-order cosine polynomial (0 beyond pi/2), and the state is set
// to 0 after each 64-sample block when it is denormal (PD_BIGORSMALL).
std::vector<float> pd_bp_impulse_response(float f, float q, float sr, float impulse, std::size_t frames) {
  if (f < 0.001) f = 10;
  if (q < 0) q = 0;
  const float omega = f * (2.0f * 3.14159f) / sr;
  float oneminusr = q < 0.001 ? 1.0f : omega / q;
  if (oneminusr > 1.0f) oneminusr = 1.0f;
  const float r = 1.0f - oneminusr;
  float qcos = 0.0f;
  if (omega >= -(0.5f * 3.14159f) && omega <= 0.5f * 3.14159f) {
    const float g = omega * omega;
    qcos = float(((g * g * g * (-1.0f / 720.0f) + g * g * (1.0f / 24.0f)) - g * 0.5) + 1);
  }
  const float coef1 = 2.0f * qcos * r, coef2 = -r * r, gain = 2 * oneminusr * (oneminusr + r * omega);
  std::vector<float> out(frames);
  float last = 0.0f, prev = 0.0f;
  for (std::size_t block = 0; block * 64 < frames; ++block) {
    for (std::size_t i = block * 64; i < std::min(frames, block * 64 + 64); ++i) {
      const float in = i == 0 ? impulse : 0.0f;
      const float output = in + coef1 * last + coef2 * prev;
      out[i] = gain * output;
      prev = last;
      last = output;
    }
    if (std::fpclassify(last) == FP_SUBNORMAL) last = 0;
    if (std::fpclassify(prev) == FP_SUBNORMAL) prev = 0;
  }
  return out;
}

ModalModel three_modes() {
  ModalModel m;
  m.modes = {{523.0, 3.0, 0.8, 0.0}, {1410.0, 9.0, 0.5, 1.0}, {4020.0, 30.0, 0.3, 0.0}};
  return m;
}

}  // namespace

TEST(BandpassBank, EverySampleIsPdsRecursionTimesTheAmplitudesSummed) {
  const ModalModel m = three_modes();
  const std::vector<double> q = {1000.0, 1500.0, 3000.0};
  const std::size_t frames = 44100;
  const std::vector<float> y = render_bandpass(m, q, 0.7, 0.0, 44100.0, frames);
  std::vector<std::vector<float>> filters;
  for (std::size_t n = 0; n < 3; ++n)
    filters.push_back(pd_bp_impulse_response(float(m.modes[n].freq_hz), float(q[n]), 44100.0f, 0.7f, frames));
  // Equal up to float rounding (the compiler may fuse multiply-adds differently in the two loops): a
  // wrong coefficient, gain or pi (3.14159 against pi drifts the phase by 3e-3 over the second) is far
  // outside this.
  float peak = 0.0f;
  for (float v : y) peak = std::max(peak, std::abs(v));
  for (std::size_t i = 0; i < frames; ++i) {
    float sum = 0.0f;
    for (std::size_t n = 0; n < 3; ++n) sum += filters[n][i] * float(m.modes[n].amp);
    ASSERT_NEAR(y[i], sum, 1e-4f * peak) << "sample " << i;
  }
  EXPECT_GT(std::abs(y[100]), 0.0f);
}

TEST(BandpassBank, DecaysAtTheFilterPoleRadiusAndStartsNearTwoOmegaOverQ) {
  // An impulse through w[n] = x[n] + 2 r cos(omega) w[n-1] - r^2 w[n-2] rings as r^n sin((n+1) omega) /
  // sin(omega), so the envelope falls by r per sample (a decay of 2 pi f / Q per second) and the output
  // (times gain ~ 2 omega^2 / Q) starts at about 2 omega / Q.
  ModalModel m;
  m.modes = {{1000.0, 0.0, 1.0, 0.0}};
  const double fs = 44100.0, Q = 500.0, omega = 2.0 * std::numbers::pi * 1000.0 / fs;
  const std::vector<float> y = render_bandpass(m, {Q}, 1.0, 0.0, fs, 44100);
  auto envelope = [&](std::size_t from) {
    float top = 0.0f;
    for (std::size_t i = from; i < from + 200; ++i) top = std::max(top, std::abs(y[i]));
    return double(top);
  };
  const double decay_per_s = std::log(envelope(0) / envelope(22050)) / (22050.0 / fs);
  EXPECT_NEAR(decay_per_s, 2.0 * std::numbers::pi * 1000.0 / Q, 0.01 * 2.0 * std::numbers::pi * 1000.0 / Q);
  EXPECT_NEAR(envelope(0), 2.0 * omega / Q, 0.02 * 2.0 * omega / Q);
}

TEST(BandpassBank, AboveAQuarterOfTheRateTheTruncatedCosineIsZero) {
  const PdBandpassCoefficients below = pd_bandpass_coefficients(11000.0, 1000.0, 44100.0);
  const PdBandpassCoefficients above = pd_bandpass_coefficients(11100.0, 1000.0, 44100.0);
  EXPECT_GT(below.coef1, 0.0f);
  EXPECT_EQ(above.coef1, 0.0f);  // rings at fs/4 whatever its centre, as in Pd
  EXPECT_LT(above.coef2, 0.0f);
}

TEST(BandpassBank, TheClipperBoundsALoudImpactAndStreamingChangesNothing) {
  const ModalModel m = three_modes();
  const std::vector<float> loud = render_bandpass(m, {1000.0}, 10000.0, 1.0, 44100.0, 4410);
  const std::vector<float> free = render_bandpass(m, {1000.0}, 10000.0, 0.0, 44100.0, 4410);
  EXPECT_EQ(*std::max_element(loud.begin(), loud.end()), 1.0f);
  EXPECT_EQ(*std::min_element(loud.begin(), loud.end()), -1.0f);
  EXPECT_GT(*std::max_element(free.begin(), free.end()), 1.5f);
  for (std::size_t i = 0; i < loud.size(); ++i) ASSERT_EQ(loud[i], std::clamp(free[i], -1.0f, 1.0f)) << i;

  BandpassBank bank(m, {1000.0}, 10000.0, 1.0, 44100.0);
  std::vector<float> pieces(4410);
  bank.render(pieces.data(), 100);  // a piece shorter than Pd's block, then the rest
  bank.render(pieces.data() + 100, 4310);
  EXPECT_EQ(pieces, loud);
}

TEST(BandpassBank, OneQForAllOrOnePerModeAndModesThatCannotSoundAreLeftOut) {
  ModalModel m = three_modes();
  EXPECT_THROW(BandpassBank(m, {1000.0, 2000.0}, 1.0, 1.0, 44100.0), std::invalid_argument);
  m.modes.push_back({30000.0, 1.0, 1.0, 0.0});  // above Nyquist
  const BandpassBank bank(m, {1000.0, 1500.0, 3000.0, 10.0}, 1.0, 1.0, 44100.0);
  EXPECT_EQ(bank.filter_count(), 3u);
}

TEST(BandpassBank, TheThesisTwoQRangesByName) {
  EXPECT_EQ(material_q(BandpassMaterial::plastic), 1000.0);  // Table 4.1, the default
  EXPECT_EQ(material_q(BandpassMaterial::wood), 1500.0);
  EXPECT_EQ(material_q(BandpassMaterial::ceramic), 3000.0);
  EXPECT_EQ(material_q(BandpassMaterial::glass), 3500.0);
  EXPECT_EQ(material_q(BandpassMaterial::metal), 4000.0);
  EXPECT_DOUBLE_EQ(material_q(BandpassMaterial::plastic, QTable::section_4_3_1_2), 20.0);
  EXPECT_DOUBLE_EQ(material_q(BandpassMaterial::metal, QTable::section_4_3_1_2), 5000.0);
  EXPECT_NEAR(material_q(BandpassMaterial::ceramic, QTable::section_4_3_1_2), std::sqrt(20.0 * 5000.0), 1e-9);
  EXPECT_EQ(enum_name(kQTableNames, QTable::section_4_3_1_2), "section_4_3_1_2");
}
