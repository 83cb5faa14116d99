// Residual transfer (Algorithm 1): on the source object itself it is the identity; a target mode
// elsewhere moves the residual beside it by the same shift, a slower decay stretches it in time by the
// decay ratio, a louder mode scales it by the power ratio, and neighbourhoods are stitched per mode.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "residual_fixture.hpp"
#include "synthesis/residual_transfer.hpp"

using namespace ms;

namespace {

constexpr double kFs = 44100.0;

// A residual whose power is a Gaussian band around each centre (Hz, width in Hz) decaying at decay_per_s.
ResidualSpectrogram banded_residual(const std::vector<Mode>& modes, const std::vector<double>& centres_hz,
                                    double width_hz, double decay_per_s, std::size_t frames) {
  ResidualSpectrogram r;
  r.sample_rate_hz = kFs;
  r.frames = frames;
  r.modes = modes;
  const std::size_t bins = r.grid.bins();
  r.power.assign(frames * bins, 0.0f);
  for (std::size_t m = 0; m < frames; ++m) {
    const double t = double(m * r.grid.hop) / kFs;
    for (std::size_t k = 0; k < bins; ++k) {
      const double f = double(k) * kFs / double(r.grid.fft_size);
      double p = 0.0;
      for (double c : centres_hz) p += std::exp(-0.5 * std::pow((f - c) / width_hz, 2.0));
      r.power[m * bins + k] = float(p * std::exp(-2.0 * decay_per_s * t));
    }
  }
  return r;
}

double total(const std::vector<float>& p) {
  double s = 0.0;
  for (float v : p) s += v;
  return s;
}

// Power-weighted mean frequency [Hz] of the bins in [lo_hz, hi_hz).
double centroid_hz(const std::vector<float>& p, const StftGrid& g, double lo_hz, double hi_hz) {
  double num = 0.0, den = 0.0;
  const std::size_t bins = g.bins();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double f = double(i % bins) * kFs / double(g.fft_size);
    if (f < lo_hz || f >= hi_hz) continue;
    num += f * p[i];
    den += p[i];
  }
  return num / den;
}

// Power-weighted mean time [s].
double mean_time_s(const std::vector<float>& p, const StftGrid& g) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double t = double((i / g.bins()) * g.hop) / kFs;
    num += t * p[i];
    den += p[i];
  }
  return num / den;
}

}  // namespace

TEST(ResidualTransfer, ToTheSameObjectIsTheIdentity) {
  const std::vector<Mode> modes = {Mode{440.0, 6.0, 0.3, 0.0}, Mode{1210.0, 15.0, 0.1, 1.0},
                                   Mode{2630.0, 40.0, 0.05, 2.0}, Mode{5100.0, 90.0, 0.02, 0.5}};
  ResidualSpectrogram r = banded_residual(modes, {700.0, 3000.0, 9000.0}, 150.0, 30.0, 120);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> jitter(0.5f, 1.5f);
  for (float& v : r.power) v *= jitter(rng);
  const std::vector<float> same = transfer_residual_power(r, modes, r.frames);
  ASSERT_EQ(same.size(), r.power.size());
  double error = 0.0, energy = 0.0;
  for (std::size_t i = 0; i < same.size(); ++i) {
    error += std::pow(double(same[i]) - r.power[i], 2.0);
    energy += std::pow(double(r.power[i]), 2.0);
  }
  EXPECT_LE(10.0 * std::log10(std::max(error, 1e-300) / energy), -30.0);
  EXPECT_EQ(same, r.power);  // every shift 0, every ratio 1: bit for bit
  // The order the modes are listed in does not matter.
  const std::vector<Mode> shuffled = {modes[2], modes[0], modes[3], modes[1]};
  EXPECT_EQ(transfer_residual_power(r, shuffled, r.frames), r.power);
}

TEST(ResidualTransfer, ToTheSameObjectThroughGriffinLim) {
  // A consistent residual (the power of a real decaying noise burst): the time signal rebuilt on the
  // same object has the source residual's spectrogram within -20 dB.
  const std::vector<Mode> modes = {Mode{500.0, 10.0, 0.2, 0.0}, Mode{1800.0, 30.0, 0.1, 0.0}};
  constexpr std::size_t samples = 22050;
  const ResidualSpectrogram r = test::noise_burst_residual(modes, 0.1, 40.0, samples, 8);
  const GriffinLimResult out = render_transferred_residual(r, modes, kFs, samples);
  EXPECT_LE(out.spectral_convergence_db, -20.0);
  RecordProperty("spectral_convergence_db", std::to_string(out.spectral_convergence_db));
  EXPECT_LE(spectral_convergence_db(out.samples, r.power, r.grid), -20.0);
  const GriffinLimResult again = render_transferred_residual(r, modes, kFs, samples);
  EXPECT_EQ(out.samples, again.samples);
  EXPECT_THROW(render_transferred_residual(r, modes, 48000.0, samples), std::invalid_argument);
}

TEST(ResidualTransfer, ShiftsWithTheMode) {
  const StftGrid g;
  const ResidualSpectrogram r = banded_residual({Mode{1000.0, 20.0, 0.2, 0.0}}, {1200.0}, 60.0, 20.0, 80);
  const std::vector<float> moved = transfer_residual_power(r, {Mode{1500.0, 20.0, 0.2, 0.0}}, r.frames);
  const double bin_hz = kFs / double(g.fft_size);
  EXPECT_NEAR(centroid_hz(r.power, g, 0.0, kFs), 1200.0, 0.5 * bin_hz);
  EXPECT_NEAR(centroid_hz(moved, g, 0.0, kFs), 1700.0, 0.5 * bin_hz);
  EXPECT_NEAR(10.0 * std::log10(total(moved) / total(r.power)), 0.0, 0.2);
}

TEST(ResidualTransfer, StretchesInTimeByTheDecayRatio) {
  const StftGrid g;
  const ResidualSpectrogram r = banded_residual({Mode{1000.0, 40.0, 0.2, 0.0}}, {1300.0}, 80.0, 40.0, 300);
  const std::vector<float> slower = transfer_residual_power(r, {Mode{1000.0, 20.0, 0.2, 0.0}}, r.frames);
  // Half the decay: target frame 2j reads source frame j, scaled by one factor in every frame after
  // the strike's (the two modes' ratio, constant once both decay exponentially).
  const std::size_t bins = g.bins(), k = std::size_t(std::lround(1300.0 * double(g.fft_size) / kFs));
  const double first = slower[2 * 3 * bins + k] / r.power[3 * bins + k];
  for (std::size_t j = 3; j < 50; ++j)  // while the source mode is within 120 dB of its start
    EXPECT_NEAR(slower[2 * j * bins + k] / r.power[j * bins + k], first, 1e-3 * first) << j;
  EXPECT_GT(mean_time_s(slower, g), 2.0 * mean_time_s(r.power, g));
  // It now decays like the target mode: 20 1/s in amplitude, 40 1/s in power.
  const std::size_t m0 = 20, m1 = 60;
  const double dt = double((m1 - m0) * g.hop) / kFs;
  EXPECT_NEAR(-std::log(slower[m1 * bins + k] / slower[m0 * bins + k]) / dt, 40.0, 0.5);
}

TEST(ResidualTransfer, ScalesByTheModesPowerRatio) {
  const ResidualSpectrogram r = banded_residual({Mode{800.0, 25.0, 0.1, 0.0}}, {900.0}, 100.0, 25.0, 100);
  const std::vector<float> louder = transfer_residual_power(r, {Mode{800.0, 25.0, 0.2, 0.0}}, r.frames);
  EXPECT_NEAR(total(louder) / total(r.power), 4.0, 4e-5);
  const std::vector<float> silent = transfer_residual_power(r, {Mode{800.0, 25.0, 0.0, 0.0}}, r.frames);
  EXPECT_EQ(total(silent), 0.0);
}

TEST(ResidualTransfer, StitchesOneNeighbourhoodPerMode) {
  const StftGrid g;
  const std::vector<Mode> source = {Mode{500.0, 10.0, 0.2, 0.0}, Mode{2000.0, 10.0, 0.2, 0.0}};
  const std::vector<Mode> target = {Mode{600.0, 10.0, 0.2, 0.0}, Mode{3000.0, 10.0, 0.2, 0.0}};
  const ResidualSpectrogram r = banded_residual(source, {550.0, 2100.0}, 40.0, 10.0, 60);
  const std::vector<float> out = transfer_residual_power(r, target, r.frames);
  const double bin_hz = kFs / double(g.fft_size);
  // The boundary between the target neighbourhoods is 1800 Hz (between 600 and 3000).
  EXPECT_NEAR(centroid_hz(out, g, 0.0, 1800.0), 650.0, bin_hz);
  EXPECT_NEAR(centroid_hz(out, g, 1800.0, kFs), 3100.0, bin_hz);
}

TEST(ResidualTransfer, WithoutTargetModesTheSourceIsKept) {
  const ResidualSpectrogram r = banded_residual({Mode{500.0, 10.0, 0.2, 0.0}}, {700.0}, 50.0, 10.0, 30);
  const std::vector<float> longer = transfer_residual_power(r, {Mode{30000.0, 10.0, 0.2, 0.0}}, 40);
  ASSERT_EQ(longer.size(), 40 * r.grid.bins());
  EXPECT_TRUE(std::equal(r.power.begin(), r.power.end(), longer.begin()));
  EXPECT_EQ(total(std::vector<float>(longer.begin() + std::ptrdiff_t(r.power.size()), longer.end())), 0.0);
}

TEST(ResidualTransfer, HeardModesCarryStrikeGainAndContact) {
  const std::vector<Mode> modes = {Mode{200.0, 5.0, 0.5, 0.0}, Mode{8000.0, 50.0, 0.5, 0.0}};
  Excitation strike;
  strike.gain = 2.0;
  const std::vector<Mode> impulse = heard_modes(modes, strike);
  EXPECT_DOUBLE_EQ(impulse[0].amp, 1.0);
  EXPECT_DOUBLE_EQ(impulse[1].amp, 1.0);
  strike.shape = PulseShape::raised_cosine;
  strike.contact_s = 0.5e-3;
  const std::vector<Mode> contact = heard_modes(modes, strike);
  EXPECT_NEAR(contact[0].amp, 1.0, 0.01);  // 200 Hz hardly feels a 0.5 ms contact
  EXPECT_LT(contact[1].amp, 0.2);          // 8 kHz is far above 1/tau = 2 kHz: strongly low-passed
  EXPECT_NEAR(contact[1].amp, std::abs(2.0 * 0.5 * contact_factor(strike, 50.0, 8000.0)) * std::exp(-50.0 * 0.5e-3), 1e-12);
  // A mode that dies within the contact is heard as what is left of it when the contact ends.
  const std::vector<Mode> fast = heard_modes({Mode{12000.0, 6e5, 1.0, 0.0}}, strike);
  EXPECT_LT(fast[0].amp, 2.0);
}

TEST(ResidualTransfer, ModesThatDieAtOnceLeaveFinitePowers) {
  // A stiff material's top modes decay at 1e4-1e5 1/s: their neighbourhoods still get finite powers.
  const std::vector<Mode> source = {Mode{500.0, 10.0, 0.2, 0.0}, Mode{15000.0, 2e4, 1e-3, 0.0}};
  const std::vector<Mode> target = {Mode{400.0, 8.0, 0.2, 0.0}, Mode{19000.0, 9e4, 1e-4, 0.0}};
  const ResidualSpectrogram r = banded_residual(source, {600.0, 12000.0, 16000.0}, 300.0, 20.0, 100);
  const std::vector<float> out = transfer_residual_power(r, target, r.frames);
  for (float v : out) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
  EXPECT_GT(total(out), 0.0);
}

TEST(ResidualTransfer, ASourceModeAtANodeAmplifiesNothingWithoutBound) {
  // The second source mode was hardly struck (1e-9 of the first); the target's is loud.
  const std::vector<Mode> source = {Mode{500.0, 10.0, 0.2, 0.0}, Mode{3000.0, 30.0, 2e-10, 0.0}};
  const std::vector<Mode> target = {Mode{500.0, 10.0, 0.2, 0.0}, Mode{3000.0, 30.0, 0.2, 0.0}};
  const ResidualSpectrogram r = banded_residual(source, {3100.0}, 100.0, 20.0, 50);
  const std::vector<float> out = transfer_residual_power(r, target, r.frames);
  EXPECT_NEAR(total(out) / total(r.power), 1.0, 1e-6);  // left as it was
  // A weak but audible source mode (-60 dB) scales its neighbourhood, at most by kMaxPixelScale.
  ResidualSpectrogram weak = r;
  weak.modes[1].amp = 2e-4;
  const double gain = total(transfer_residual_power(weak, target, r.frames)) / total(r.power);
  EXPECT_GT(gain, 1e5);
  EXPECT_LE(gain, kMaxPixelScale * (1 + 1e-6));
}
