// The residual of an estimate: a known burst added to a modal sound is what the residual holds (its
// energy within 1 dB, in the burst's band and nowhere else), and write_residual puts it beside the
// material file in a form the synthesis side reads back.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <stdexcept>

#include "analysis/estimation/residual.hpp"
#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/residual_transfer.hpp"
#include "synthesis/resonator_bank.hpp"

using namespace ms;

namespace {

constexpr double kFs = 44100.0;

// Band-limited noise: 300 random-phase sines between lo_hz and hi_hz under a Hann envelope of
// length_s starting at start_s, peak about `level`.
std::vector<float> burst(std::size_t samples, double start_s, double length_s, double lo_hz, double hi_hz,
                         double level, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<float> x(samples, 0.0f);
  const std::size_t n0 = std::size_t(start_s * kFs), len = std::size_t(length_s * kFs);
  std::vector<double> acc(len, 0.0);
  for (int s = 0; s < 300; ++s) {
    const double f = lo_hz + (hi_hz - lo_hz) * u(rng), phase = 2 * std::numbers::pi * u(rng);
    for (std::size_t n = 0; n < len; ++n) acc[n] += std::sin(2 * std::numbers::pi * f * double(n) / kFs + phase);
  }
  for (std::size_t n = 0; n < len && n0 + n < samples; ++n) {
    const double envelope = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * double(n) / double(len));
    x[n0 + n] = float(level * envelope * acc[n] / std::sqrt(150.0));
  }
  return x;
}

// Energy of a power spectrogram in the bins of [lo_hz, hi_hz).
double band_energy(const std::vector<float>& power, const StftGrid& g, double lo_hz, double hi_hz) {
  double e = 0.0;
  for (std::size_t i = 0; i < power.size(); ++i) {
    const double f = double(i % g.bins()) * kFs / double(g.fft_size);
    if (f >= lo_hz && f < hi_hz) e += power[i];
  }
  return e;
}

double band_energy(const std::vector<double>& power, const StftGrid& g, double lo_hz, double hi_hz) {
  return band_energy(std::vector<float>(power.begin(), power.end()), g, lo_hz, hi_hz);
}

// A three-mode object for E/rho = 1 and a Rayleigh material that puts its modes at about 440, 1250 and
// 2600 Hz, away from the bursts.
ObjectEigen three_modes() {
  ObjectEigen o;
  for (double f : {440.0, 1250.0, 2600.0}) o.lambda0.push_back(std::pow(2 * std::numbers::pi * f, 2.0) / 1e5);
  o.gain = {1.0, -0.6, 0.4};
  return o;
}

}  // namespace

TEST(Residual, AKnownBurstIsRecoveredInItsBand) {
  const std::size_t samples = 44100;
  ModalModel model;
  model.modes = {Mode{440.0, 4.0, 0.3, 0.0}, Mode{1250.0, 12.0, 0.2, 0.0}, Mode{2600.0, 30.0, 0.1, 0.0}};
  const std::vector<float> modal = render_bank(model, Excitation{}, kFs, samples);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const std::vector<float> added = burst(samples, 0.05, 0.04, 5000.0, 7000.0, 0.05, seed);
    std::vector<float> recording(samples);
    for (std::size_t n = 0; n < samples; ++n) recording[n] = modal[n] + added[n];
    const ResidualSpectrogram r = residual_spectrogram(recording, modal, kFs, model.modes);
    ASSERT_EQ(r.frames, r.grid.frames_for(samples));
    Stft stft(r.grid);
    const std::vector<double> truth = stft.power(added);
    const double in_band = band_energy(r.power, r.grid, 4800.0, 7200.0);
    const double truth_in_band = band_energy(truth, r.grid, 4800.0, 7200.0);
    EXPECT_NEAR(10.0 * std::log10(in_band / truth_in_band), 0.0, 1.0) << seed;
    RecordProperty("burst_energy_error_db_seed_" + std::to_string(seed), std::to_string(10.0 * std::log10(in_band / truth_in_band)));
    // Nothing of the modes is left: outside the burst's band the residual holds < 1 % of its energy.
    const double outside = band_energy(r.power, r.grid, 0.0, 4500.0) + band_energy(r.power, r.grid, 7500.0, kFs);
    EXPECT_LT(outside, 0.01 * in_band) << seed;
    // And in time it sits where the burst was: 50-90 ms, frames 8-16 at a 5.8 ms hop, +- one window.
    double inside_time = 0.0, all = 0.0;
    for (std::size_t i = 0; i < r.power.size(); ++i) {
      const double t = double((i / r.grid.bins()) * r.grid.hop) / kFs;
      all += r.power[i];
      if (t >= 0.05 - 0.012 && t <= 0.09 + 0.012) inside_time += r.power[i];
    }
    EXPECT_GT(inside_time, 0.99 * all) << seed;
  }
}

TEST(Residual, TheEstimatesResidualIsTheBurstAndItsModesAreTheHeardOnes) {
  const ObjectEigen object = three_modes();
  const Candidate material{8.0, 2e-6, 1e5, 0.3};
  Excitation strike;
  strike.shape = PulseShape::raised_cosine;
  strike.contact_s = 0.3e-3;
  const ModalModel model = candidate_model(object, material, 0.5 * kFs);
  ASSERT_EQ(model.modes.size(), 3u);
  const std::size_t samples = 30000;
  const std::vector<float> modal = render_bank(model, strike, kFs, samples);
  const std::vector<float> added = burst(samples, 0.0, 0.03, 8000.0, 11000.0, 0.03, 9);
  std::vector<float> recording(samples);
  for (std::size_t n = 0; n < samples; ++n) recording[n] = modal[n] + added[n];
  const ResidualSpectrogram r = estimate_residual(recording, kFs, object, strike, material);
  Stft stft(r.grid);
  const std::vector<double> truth = stft.power(added);
  EXPECT_NEAR(10.0 * std::log10(band_energy(r.power, r.grid, 7800.0, 11200.0) /
                                band_energy(truth, r.grid, 7800.0, 11200.0)),
              0.0, 1.0);
  const std::vector<Mode> heard = heard_modes(model.modes, strike);
  ASSERT_EQ(r.modes.size(), heard.size());
  for (std::size_t i = 0; i < heard.size(); ++i) {
    EXPECT_EQ(r.modes[i].freq_hz, heard[i].freq_hz);
    EXPECT_EQ(r.modes[i].amp, heard[i].amp);
  }
}

TEST(Residual, CoversAtMostTheStatedDuration) {
  const std::vector<float> recording(3 * 44100, 0.01f), synthesis(100, 0.0f);
  const std::vector<Mode> modes = {Mode{440.0, 4.0, 0.3, 0.0}};
  ResidualOptions options;
  options.max_duration_s = 0.5;
  const ResidualSpectrogram r = residual_spectrogram(recording, synthesis, kFs, modes, options);
  EXPECT_EQ(r.frames, r.grid.frames_for(22050));
  EXPECT_THROW(residual_spectrogram({}, synthesis, kFs, modes), std::invalid_argument);
  EXPECT_THROW(residual_spectrogram(recording, synthesis, kFs, {Mode{30000.0, 4.0, 0.3, 0.0}}), std::invalid_argument);
}

TEST(Residual, WrittenBesideTheMaterialAndReadBack) {
  EXPECT_EQ(residual_path_for("out/wood.yaml"), "out/wood.residual.msr");
  EXPECT_EQ(residual_path_for("wood"), "wood.residual.msr");
  const ObjectEigen object = three_modes();
  const Candidate material{8.0, 2e-6, 1e5, 0.3};
  const std::vector<float> recording = burst(20000, 0.0, 0.02, 6000.0, 8000.0, 0.1, 4);
  test::TempDir dir;
  const std::string material_path = dir.file("wood.yaml");
  const std::string written =
      write_residual(material_path, recording, kFs, object, Excitation{}, material, "modalstudy estimate wood.wav");
  EXPECT_EQ(written, dir.file("wood.residual.msr"));
  const ResidualSpectrogram back = read_residual_file(written);
  const ResidualSpectrogram direct = estimate_residual(recording, kFs, object, Excitation{}, material);
  EXPECT_EQ(back.source, "modalstudy estimate wood.wav");
  EXPECT_EQ(back.power, direct.power);
  EXPECT_EQ(back.modes.size(), 3u);
  // A bad folder: nothing anywhere.
  EXPECT_THROW(write_residual(dir.file("missing/wood.yaml"), recording, kFs, object, Excitation{}, material, ""),
               InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("missing")));
}
