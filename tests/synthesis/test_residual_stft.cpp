// The residual's STFT: the least-squares inverse undoes the forward transform, and the closed-form
// power of a damped sinusoid equals the transform of its samples, edge frames included.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>

#include "synthesis/residual_stft.hpp"

using namespace ms;

TEST(ResidualStft, GridCountsFramesAndBins) {
  const StftGrid g;
  EXPECT_EQ(g.bins(), 513u);
  EXPECT_EQ(g.frames_for(0), 1u);
  EXPECT_EQ(g.frames_for(255), 1u);
  EXPECT_EQ(g.frames_for(256), 2u);
  EXPECT_EQ(g.frames_for(44100), 173u);
  EXPECT_THROW(Stft(StftGrid{15, 4}), std::invalid_argument);
  EXPECT_THROW(Stft(StftGrid{64, 33}), std::invalid_argument);
  EXPECT_THROW(Stft(StftGrid{64, 0}), std::invalid_argument);
}

TEST(ResidualStft, InverseOfForwardIsTheSignal) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  for (std::size_t samples : {1000u, 4096u, 4097u}) {
    std::vector<double> x(samples), back(samples);
    for (double& v : x) v = normal(rng);
    Stft stft(StftGrid{});
    std::vector<std::complex<double>> spectra(stft.grid().frames_for(samples) * stft.grid().bins());
    stft.forward(x.data(), samples, spectra.data());
    stft.inverse(spectra.data(), samples, back.data());
    double worst = 0.0;
    for (std::size_t i = 0; i < samples; ++i) worst = std::max(worst, std::abs(back[i] - x[i]));
    EXPECT_LT(worst, 1e-12) << samples;
  }
}

TEST(ResidualStft, SineOfOneBinPeaksAtAmpSquaredNSquaredOverSixteen) {
  // A steady sine on a bin centre: |X| = (a/2) sum w = a N / 4 in every interior frame.
  const StftGrid g;
  const double fs = 44100.0, f = 40.0 * fs / double(g.fft_size);
  const Mode m{f, 0.0, 0.5, 0.3};
  std::vector<double> p(1);
  damped_sine_power(m, fs, g, 10, 11, 40, 41, p.data());
  EXPECT_NEAR(p[0], 0.25 * 1024.0 * 1024.0 / 16.0, 1e-6 * p[0]);
}

TEST(ResidualStft, ClosedFormPowerEqualsTheTransformOfTheSamples) {
  const StftGrid g{512, 128};
  const double fs = 48000.0;
  for (const Mode& m : {Mode{1234.5, 40.0, 0.8, 0.0}, Mode{300.0, 3.0, 1.0, 1.1}, Mode{9000.0, 600.0, 0.2, -2.0}}) {
    const std::size_t samples = 6000;
    std::vector<float> x(samples);
    for (std::size_t n = 0; n < samples; ++n) {
      const double t = double(n) / fs;
      x[n] = float(m.amp * std::exp(-m.decay_per_s * t) * std::sin(2 * std::numbers::pi * m.freq_hz * t + m.phase_rad));
    }
    Stft stft(g);
    const std::vector<double> numeric = stft.power(x);
    const std::size_t frames = g.frames_for(samples), bins = g.bins();
    std::vector<double> closed(frames * bins);
    damped_sine_power(m, fs, g, 0, frames, 0, bins, closed.data());
    double peak = 0.0;
    for (double v : numeric) peak = std::max(peak, v);
    // The closed form rings on past the rendered samples: compare the frames wholly inside them.
    const std::size_t inside = (samples - g.fft_size / 2) / g.hop + 1;
    double worst = 0.0;
    for (std::size_t i = 0; i < inside * bins; ++i) worst = std::max(worst, std::abs(closed[i] - numeric[i]));
    // Float samples carry -150 dB of rounding in power; the frames at the strike are included.
    EXPECT_LT(worst, 1e-6 * peak) << m.freq_hz;
    // A patch is the same numbers as the whole.
    std::vector<double> patch(3 * 4);
    damped_sine_power(m, fs, g, 2, 5, 10, 14, patch.data());
    for (std::size_t r = 0; r < 3; ++r)
      for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(patch[r * 4 + c], closed[(2 + r) * bins + 10 + c]);
  }
}

TEST(ResidualStft, ClosedFormStaysFiniteForAnyDecay) {
  // A mode gone within a sample (d = 5e5 1/s, as a stiff material's top modes get) and a slow one.
  const StftGrid g;
  for (const Mode& m : {Mode{18000.0, 5e5, 1e-3, 0.4}, Mode{60.0, 0.0, 2.0, 0.0}}) {
    std::vector<double> p(6 * g.bins());
    damped_sine_power(m, 44100.0, g, 0, 6, 0, g.bins(), p.data());
    for (double v : p) ASSERT_TRUE(std::isfinite(v) && v >= 0.0) << m.decay_per_s;
  }
}
