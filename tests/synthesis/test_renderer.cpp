// The resonator bank against the double-precision closed form, the minimal parameter set's exact
// output, finite-contact excitation, streaming and allocation-freedom.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <new>
#include <numbers>
#include <random>

#include "support/test_util.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/output_level.hpp"
#include "synthesis/reference_renderer.hpp"
#include "synthesis/resonator_bank.hpp"

// Counts heap allocations while g_counting is set (to prove the render loop never allocates).
static std::atomic<bool> g_counting{false};
static std::atomic<long> g_allocations{0};
void* operator new(std::size_t n) {
  if (g_counting) ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace ms;

namespace {

ModalModel random_model(std::uint64_t seed, std::size_t modes, double max_decay) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> logf(std::log(40.0), std::log(20000.0)), u(0.0, 1.0);
  ModalModel m;
  for (std::size_t i = 0; i < modes; ++i)
    m.modes.push_back(Mode{std::exp(logf(rng)), 0.05 + max_decay * u(rng), 0.05 + u(rng), 2 * std::numbers::pi * u(rng)});
  return m;
}

}  // namespace

TEST(Renderer, MinimalSetIsExactlyTheFormula) {
  // y = 1.0 e^{-3 t} sin(2 pi 440 t), float output.
  ModalModel m;
  m.modes.push_back(Mode{440.0, 3.0, 1.0, 0.0});
  const std::vector<float> y = render_bank(m, Excitation{}, 44100.0, 88200);
  double worst = 0.0;
  for (std::size_t n = 0; n < y.size(); ++n) {
    const double t = double(n) / 44100.0;
    worst = std::max(worst, std::abs(y[n] - std::exp(-3.0 * t) * std::sin(2 * std::numbers::pi * 440.0 * t)));
  }
  EXPECT_LT(worst, 1e-5);  // float rounding only (-100 dB): never drifts, thanks to re-anchoring
  EXPECT_EQ(y[0], 0.0f);
}

TEST(Renderer, BankMatchesClosedFormAbove60dB) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const ModalModel m = random_model(seed, 300, 60.0);
    const auto ref = render_reference(m, Excitation{}, 44100.0, 44100);
    const auto bank = render_bank(m, Excitation{}, 44100.0, 44100);
    EXPECT_GT(test::snr_db(ref, bank), 60.0) << "seed " << seed;
  }
}

TEST(Renderer, LongHighQModesStayAccurate) {
  // 30 s of nearly undamped modes (Q ~ 1e5): without re-anchoring float rounding would drift.
  ModalModel m;
  m.modes = {Mode{55.0, 0.002, 1.0, 0.0}, Mode{3520.7, 0.01, 0.5, 0.3}, Mode{17999.9, 0.02, 0.25, 1.0}};
  const std::size_t frames = 30 * 44100;
  const auto ref = render_reference(m, Excitation{}, 44100.0, frames);
  const auto bank = render_bank(m, Excitation{}, 44100.0, frames);
  EXPECT_GT(test::snr_db(ref, bank), 90.0);
  // Also the last second alone (where drift would show).
  const std::vector<double> ref_tail(ref.end() - 44100, ref.end());
  const std::vector<float> bank_tail(bank.end() - 44100, bank.end());
  EXPECT_GT(test::snr_db(ref_tail, bank_tail), 80.0);
}

TEST(Renderer, FiniteContactMatchesClosedForm) {
  for (PulseShape shape : {PulseShape::raised_cosine, PulseShape::hertz, PulseShape::half_sine}) {
    for (double tau : {0.0002, 0.001, 0.004}) {
      const ModalModel m = random_model(7, 120, 40.0);
      Excitation e;
      e.shape = shape;
      e.contact_s = tau;
      e.gain = 2.0;
      const auto ref = render_reference(m, e, 44100.0, 22050);
      const auto bank = render_bank(m, e, 44100.0, 22050);
      EXPECT_GT(test::snr_db(ref, bank), 60.0) << to_string(shape) << " tau " << tau;
    }
  }
}

TEST(Excitation, RaisedCosineLowPassMatchesFourierTransform) {
  // Undamped mode: G(omega) = e^{-i omega tau/2} sinc(omega tau/2) / (1 - (omega tau / 2 pi)^2).
  Excitation e;
  e.shape = PulseShape::raised_cosine;
  e.contact_s = 0.001;
  for (double f : {50.0, 300.0, 700.0, 1500.0, 4321.0, 9000.0}) {
    const double x = 2 * std::numbers::pi * f * e.contact_s / 2;
    const double expected = std::abs(std::sin(x) / x / (1 - std::pow(f * e.contact_s, 2)));
    EXPECT_NEAR(std::abs(contact_factor(e, 0.0, f)), expected, 1e-9) << f;
  }
  // Shorter contacts approach the impulse; magnitude falls with frequency (a low-pass).
  e.contact_s = 1e-6;
  EXPECT_NEAR(std::abs(contact_factor(e, 5.0, 1000.0)), 1.0, 1e-4);
  e.contact_s = 0.001;
  EXPECT_GT(std::abs(contact_factor(e, 0.0, 200.0)), std::abs(contact_factor(e, 0.0, 800.0)));
}

TEST(Excitation, HalfSineMatchesItsFourierTransform) {
  // (pi/2) sin(pi t/tau)/tau: G(p) = (pi/2tau) a (1 + e^{-p tau}) / (p^2 + a^2), a = pi/tau (damped too).
  Excitation e;
  e.shape = PulseShape::half_sine;
  e.contact_s = 0.0008;
  const double a = std::numbers::pi / e.contact_s;
  for (double d : {0.0, 30.0})
    for (double f : {50.0, 300.0, 1234.0, 1875.0, 4321.0, 9000.0}) {
      const std::complex<double> p(-d, 2 * std::numbers::pi * f);
      const std::complex<double> expected = 0.5 * a * a * (1.0 + std::exp(-p * e.contact_s)) / (p * p + a * a);
      EXPECT_NEAR(std::abs(contact_factor(e, d, f) - expected), 0.0, 1e-9) << f;
    }
}

TEST(Excitation, PulsesHaveUnitArea) {
  for (PulseShape shape : {PulseShape::raised_cosine, PulseShape::hertz, PulseShape::half_sine}) {
    Excitation e;
    e.shape = shape;
    e.contact_s = 0.002;
    const int n = 200000;
    double area = 0.0;
    for (int i = 0; i < n; ++i) area += e.force((i + 0.5) * e.contact_s / n) * e.contact_s / n;
    EXPECT_NEAR(area, 1.0, 1e-6) << to_string(shape);
  }
}

TEST(Renderer, StreamingInChunksEqualsOneShot) {
  const ModalModel m = random_model(11, 70, 20.0);
  Excitation e;
  e.shape = PulseShape::raised_cosine;
  e.contact_s = 0.0007;
  const auto whole = render_bank(m, e, 48000.0, 10000);
  ResonatorBank bank(m, e, 48000.0);
  std::vector<float> pieces(10000);
  std::size_t done = 0;
  for (std::size_t chunk : {1u, 7u, 64u, 511u, 512u, 1000u, 3u}) {
    bank.render(pieces.data() + done, chunk);
    done += chunk;
  }
  bank.render(pieces.data() + done, pieces.size() - done);
  for (std::size_t i = 0; i < whole.size(); ++i) ASSERT_EQ(whole[i], pieces[i]) << i;
}

TEST(Renderer, RenderDoesNotAllocate) {
  const ModalModel m = random_model(5, 1000, 30.0);
  ResonatorBank bank(m, Excitation{}, 44100.0);
  std::vector<float> out(44100);
  g_allocations = 0;
  g_counting = true;
  bank.render(out.data(), out.size());
  g_counting = false;
  EXPECT_EQ(g_allocations.load(), 0);
}

TEST(OutputLevel, PeakAndAttackRms) {
  std::vector<float> y(44100, 0.0f);
  for (std::size_t n = 0; n < y.size(); ++n) y[n] = float(0.1 * std::sin(2 * std::numbers::pi * 1000.0 * n / 44100.0));
  OutputLevel peak{LevelMode::peak, -6.0, 0.005};
  EXPECT_NEAR(level_gain(y, 44100.0, peak) * 0.1, std::pow(10.0, -6.0 / 20), 1e-4);
  OutputLevel attack{LevelMode::attack_rms, -20.0, 0.005};
  // RMS of a sine over 5 whole periods is amplitude / sqrt(2).
  EXPECT_NEAR(level_gain(y, 44100.0, attack) * 0.1 / std::sqrt(2.0), 0.1, 1e-3);
  EXPECT_EQ(level_gain(y, 44100.0, OutputLevel{}), 1.0);
  EXPECT_EQ(level_gain(std::vector<float>(10, 0.0f), 44100.0, peak), 1.0);  // silence: unchanged
}
