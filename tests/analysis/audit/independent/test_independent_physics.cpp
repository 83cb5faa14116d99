// The independent generator's own physics, read back from what it renders: a mode's frequency and
// decay, a contact's spectrum against the pulse's closed-form Fourier transform, the room's RT60 by
// Schroeder integration and its direct-to-reverberant ratio, the burst's band edges, the Butterworth
// response, the FFT convolution, and the case-level draws (mode spacing, strikes, jitter, noise level).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

#include "independent_burst.hpp"
#include "independent_dsp.hpp"
#include "independent_generator.hpp"
#include "independent_modes.hpp"
#include "independent_room.hpp"

namespace ms::indep {
namespace {

constexpr double kFs = 44100.0;
using cd = std::complex<double>;

// Complex amplitude c of y[i] = Im(c e^{s i / fs}) over [begin, end), by least squares.
cd fit_complex_amplitude(const std::vector<double>& y, cd s, std::size_t begin, std::size_t end) {
  Eigen::MatrixXd a(end - begin, 2);
  Eigen::VectorXd b(end - begin);
  for (std::size_t i = begin; i < end; ++i) {
    const cd z = std::exp(s * (double(i) / kFs));
    a(i - begin, 0) = z.imag();  // Im((x + iy) z) = x Im z + y Re z
    a(i - begin, 1) = z.real();
    b(i - begin) = y[i];
  }
  const Eigen::Vector2d x = a.colPivHouseholderQr().solve(b);
  return {x(0), x(1)};
}

TEST(IndependentPhysics, ModeFrequencyAndDecayReadBackByLinearPrediction) {
  const DampedMode mode{1234.5, 7.3, 0.5};
  const std::vector<double> y = render_modes({mode}, {}, kFs, 44100);
  // A damped sinusoid obeys y[i+1] = 2 r cos(w) y[i] - r^2 y[i-1]; fit the two coefficients.
  Eigen::MatrixXd a(y.size() - 2, 2);
  Eigen::VectorXd b(y.size() - 2);
  for (std::size_t i = 1; i + 1 < y.size(); ++i) {
    a(i - 1, 0) = y[i];
    a(i - 1, 1) = y[i - 1];
    b(i - 1) = y[i + 1];
  }
  const Eigen::Vector2d c = a.colPivHouseholderQr().solve(b);
  const double r = std::sqrt(-c(1)), w = std::acos(c(0) / (2.0 * r));
  EXPECT_NEAR(w * kFs / (2.0 * std::numbers::pi), 1234.5, 1e-6);
  EXPECT_NEAR(-std::log(r) * kFs, 7.3, 1e-6);
  // The recursion stays on the closed form (re-anchored every 4096 samples).
  for (std::size_t i : {std::size_t(1000), std::size_t(4095), std::size_t(30001), std::size_t(44099)}) {
    const double t = double(i) / kFs;
    EXPECT_NEAR(y[i], 0.5 * std::exp(-7.3 * t) * std::sin(2.0 * std::numbers::pi * 1234.5 * t), 1e-12) << i;
  }
}

// |F(f)| / F(0) of the unit-area pulses of duration tau, x = f tau: Hann and half-sine in elementary
// form, and the general sin^(nu-1) pulse (Gradshteyn-Ryzhik 3.892): Gamma((nu+1)/2)^2 /
// |Gamma((nu+1)/2 + x) Gamma((nu+1)/2 - x)|, nu = 5/2 for Hertz.
double hann_spectrum(double x) {
  return std::abs(std::sin(std::numbers::pi * x) / (std::numbers::pi * x * (1.0 - x * x)));
}
double half_sine_spectrum(double x) { return std::abs(std::cos(std::numbers::pi * x) / (1.0 - 4.0 * x * x)); }
double sine_power_spectrum(double nu, double x) {
  const double h = 0.5 * (nu + 1.0);
  return std::pow(std::tgamma(h), 2) / std::abs(std::tgamma(h + x) * std::tgamma(h - x));
}

TEST(IndependentPhysics, ContactSpectraMatchThePulsesClosedForms) {
  // The Gamma form reproduces the elementary ones (Hann = 2 sin^2: nu = 3; half-sine: nu = 2).
  for (double x : {0.3, 0.77, 1.3, 2.2, 4.1}) {
    EXPECT_NEAR(sine_power_spectrum(3.0, x), hann_spectrum(x), 1e-12) << x;
    EXPECT_NEAR(sine_power_spectrum(2.0, x), half_sine_spectrum(x), 1e-12) << x;
  }
  const double tau = 1e-3;
  const struct {
    ForceShape shape;
    double (*closed)(double);
  } cases[] = {{ForceShape::hann, hann_spectrum},
               {ForceShape::half_sine, half_sine_spectrum},
               {ForceShape::hertz, [](double x) { return sine_power_spectrum(2.5, x); }}};
  for (const auto& k : cases) {
    for (double f : {300.0, 730.0, 1210.0, 1830.0, 2620.0, 3710.0, 5130.0}) {
      const DampedMode mode{f, 0.2, 1.0};
      const std::vector<double> y = render_modes({mode}, {k.shape, tau}, kFs, 4410);
      const cd s(-0.2, 2.0 * std::numbers::pi * f);
      const double measured = std::abs(fit_complex_amplitude(y, s, std::size_t(tau * kFs) + 2, y.size()));
      EXPECT_NEAR(measured, k.closed(f * tau), 2e-4) << shape_name(k.shape) << " at " << f << " Hz";
    }
  }
  // The ideal impulse passes every mode at its own amplitude.
  const std::vector<double> y = render_modes({{2000.0, 3.0, 0.7}}, {}, kFs, 4410);
  EXPECT_NEAR(std::abs(fit_complex_amplitude(y, cd(-3.0, 2.0 * std::numbers::pi * 2000.0), 0, y.size())), 0.7, 1e-9);
}

// Reverberation time from the Schroeder backward integral of h^2: the line through its -5 and
// -5 - span dB points, extrapolated to 60 dB.
double schroeder_rt60(const std::vector<double>& h, double span_db) {
  std::vector<double> energy(h.size());
  double acc = 0.0;
  for (std::size_t i = h.size(); i-- > 0;) energy[i] = acc += h[i] * h[i];
  std::vector<double> t, level;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double db = 10.0 * std::log10(energy[i] / energy[0]);
    if (db <= -5.0 && db >= -5.0 - span_db) {
      t.push_back(double(i) / kFs);
      level.push_back(db);
    }
  }
  Eigen::MatrixXd a(t.size(), 2);
  Eigen::VectorXd b(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    a(i, 0) = 1.0;
    a(i, 1) = t[i];
    b(i) = level[i];
  }
  const Eigen::Vector2d c = a.colPivHouseholderQr().solve(b);
  return -60.0 / c(1);
}

TEST(IndependentPhysics, RoomRt60BySchroederIntegrationAndItsDirectToReverberantRatio) {
  RoomSpec room;
  room.rt60_s = {0.6, 0.6, 0.6, 0.6};
  room.drr_db = 3.0;
  double mean = 0.0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const std::vector<double> h = room_impulse_response(room, kFs, seed);
    std::vector<double> tail(h.begin() + 1, h.end());
    const double t30 = schroeder_rt60(tail, 30.0);
    EXPECT_NEAR(t30, 0.6, 0.06) << seed;
    mean += t30 / 6.0;
    double reverberant = 0.0;
    for (double v : tail) reverberant += v * v;
    EXPECT_NEAR(10.0 * std::log10(h[0] * h[0] / reverberant), 3.0, 1e-9);
  }
  EXPECT_NEAR(mean, 0.6, 0.03);
  // Per band: in the interior of each band (clear of the crossovers at 500, 2000 and 6000 Hz, where
  // the neighbouring bands' decays overlap) the tail decays in that band's RT60.
  room.rt60_s = {0.9, 0.7, 0.5, 0.3};
  room.drr_db = -2.0;
  const double interior_hz[4][2] = {{0.0, 250.0}, {800.0, 1250.0}, {3000.0, 4000.0}, {10000.0, 0.0}};
  for (std::size_t band = 0; band < 4; ++band) {
    double band_mean = 0.0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      const std::vector<double> h = room_impulse_response(room, kFs, seed);
      std::vector<double> tail(h.begin() + 1, h.end());
      if (interior_hz[band][0] > 0.0) {
        Butterworth4 hp = butterworth4_highpass(interior_hz[band][0], kFs);
        for (double& v : tail) v = hp.step(v);
      }
      if (interior_hz[band][1] > 0.0) {
        Butterworth4 lp = butterworth4_lowpass(interior_hz[band][1], kFs);
        for (double& v : tail) v = lp.step(v);
      }
      band_mean += schroeder_rt60(tail, 20.0) / 6.0;
    }
    EXPECT_NEAR(band_mean, room.rt60_s[band], 0.1 * room.rt60_s[band]) << "band " << band;
  }
}

TEST(IndependentPhysics, ButterworthSectionsAreTheBilinearButterworthResponse) {
  const double fc = 2000.0;
  const Butterworth4 lp = butterworth4_lowpass(fc, kFs), hp = butterworth4_highpass(fc, kFs);
  auto gain = [](const Butterworth4& f, double freq) {
    const cd z = std::exp(cd(0.0, -2.0 * std::numbers::pi * freq / kFs));
    cd h = 1.0;
    for (const Biquad& b : f.sections) h *= (b.b0 + b.b1 * z + b.b2 * z * z) / (1.0 + b.a1 * z + b.a2 * z * z);
    return std::abs(h);
  };
  for (double f : {200.0, 1000.0, 2000.0, 3000.0, 8000.0, 15000.0}) {
    // |H|^2 = 1 / (1 + (tan(pi f/fs) / tan(pi fc/fs))^(+-8)): the analog Butterworth, prewarped.
    const double r = std::tan(std::numbers::pi * f / kFs) / std::tan(std::numbers::pi * fc / kFs);
    EXPECT_NEAR(gain(lp, f), 1.0 / std::sqrt(1.0 + std::pow(r, 8)), 1e-9) << f;
    EXPECT_NEAR(gain(hp, f), 1.0 / std::sqrt(1.0 + std::pow(r, -8)), 1e-9) << f;
  }
  EXPECT_NEAR(20.0 * std::log10(gain(lp, fc)), -3.0103, 1e-3);
}

TEST(IndependentPhysics, BurstBandEdgesFromItsSpectrum) {
  const BurstSpec spec{0.015, 1000.0, 6000.0, 0.05};
  std::mt19937_64 rng(5);
  const std::size_t n = 4096;
  std::vector<double> power(n / 2 + 1, 0.0);
  for (int k = 0; k < 300; ++k) {
    const std::vector<double> b = attack_burst(spec, kFs, rng);
    ASSERT_EQ(b.size(), std::size_t(std::lround(0.015 * kFs)));
    EXPECT_NEAR(rms_of(b, 0, b.size()), 0.05, 1e-12);
    EXPECT_LT(std::abs(b.back()), 0.01 * 0.05 * 10.0);  // the envelope closes at the end
    for (std::size_t j = 0; j <= n / 2; ++j) {
      cd acc = 0.0;
      if (j % 4 != 0) continue;  // every 4th bin (43 Hz) is enough for the edges
      for (std::size_t i = 0; i < b.size(); ++i) acc += b[i] * std::exp(cd(0.0, -2.0 * std::numbers::pi * double(j * i) / double(n)));
      power[j] += std::norm(acc);
    }
  }
  auto bin_hz = [&](std::size_t j) { return double(j) * kFs / double(n); };
  double passband = 0.0;
  int count = 0;
  for (std::size_t j = 0; j <= n / 2; j += 4)
    if (bin_hz(j) >= 2000.0 && bin_hz(j) <= 3000.0) passband += power[j], ++count;
  passband /= count;
  double low = 0.0, high = 0.0;
  for (std::size_t j = 4; j <= n / 2; j += 4) {
    const double a = 10.0 * std::log10(power[j - 4] / passband), b = 10.0 * std::log10(power[j] / passband);
    const double cross = bin_hz(j - 4) + (bin_hz(j) - bin_hz(j - 4)) * (-3.0 - a) / (b - a);
    if (a < -3.0 && b >= -3.0 && low == 0.0) low = cross;
    if (a >= -3.0 && b < -3.0 && bin_hz(j) > 3000.0) high = cross;
  }
  EXPECT_NEAR(low, 1000.0, 80.0);
  EXPECT_NEAR(high, 6000.0, 480.0);
}

TEST(IndependentPhysics, FftConvolutionIsTheDirectSum) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> x(1000), h(300);
  for (double& v : x) v = normal(rng);
  for (double& v : h) v = normal(rng);
  const std::vector<double> y = convolve_fft(x, h, 1299);
  for (std::size_t i = 0; i < y.size(); i += 7) {
    double direct = 0.0;
    for (std::size_t k = 0; k < h.size(); ++k)
      if (i >= k && i - k < x.size()) direct += h[k] * x[i - k];
    EXPECT_NEAR(y[i], direct, 1e-10) << i;
  }
}

TEST(IndependentPhysics, CasesKeepTheirRanges) {
  for (std::uint64_t seed = 500; seed < 520; ++seed) {
    const IndependentCase c = generate_independent_case(seed, {}, {});
    ASSERT_GE(c.object.size(), 15u);
    ASSERT_LE(c.object.size(), 40u);
    for (std::size_t n = 1; n < c.object.size(); ++n) {
      const double gap = c.object[n].freq_hz - c.object[n - 1].freq_hz;
      EXPECT_GE(gap, std::max(0.015 * c.object[n - 1].freq_hz, 10.0)) << seed;
    }
    ASSERT_GE(c.recordings.size(), 6u);
    ASSERT_LE(c.recordings.size(), 10u);
    double softest = 0.0, loudest = -100.0;
    for (std::size_t s = 0; s < c.strikes.size(); ++s) {
      softest = std::min(softest, c.strikes[s].gain_db);
      loudest = std::max(loudest, c.strikes[s].gain_db);
      const double seconds = double(c.recordings[s].samples.size() - c.strikes[s].pre_roll_frames) / kFs;
      EXPECT_GE(seconds, 1.0);
      EXPECT_LE(seconds, 2.1);
      float peak = 0.0f;
      for (float v : c.recordings[s].samples) peak = std::max(peak, std::abs(v));
      EXPECT_LT(peak, 0.95f);
    }
    EXPECT_GE(loudest - softest, 17.0);
    EXPECT_LE(loudest - softest, 23.0);
    EXPECT_GE(c.jitter_db, 1.0);
    EXPECT_LE(c.jitter_db, 3.0);
    EXPECT_GE(c.noise_below_db, 80.0);
  }
  // A doublet: two modes a few Hz apart replace one.
  const IndependentCase d = generate_independent_case(501, {"mode_doublet"}, {0.5});
  const IndependentCase clean = generate_independent_case(501, {}, {});
  const std::size_t extra = d.strikes[0].modes.size() - clean.strikes[0].modes.size();
  EXPECT_GE(extra, 1u);
  EXPECT_LE(extra, 2u);
  for (std::size_t n = 1; n < d.strikes[0].modes.size(); ++n) {
    const double gap = d.strikes[0].modes[n].freq_hz - d.strikes[0].modes[n - 1].freq_hz;
    if (gap < 7.0) {
      EXPECT_NEAR(gap, 4.0, 1e-9);
    }
  }
  // Contacts shorten with the strike as gain^-p, 0.4-1.5 ms at the softest.
  const IndependentCase k = generate_independent_case(502, {"contact_duration"}, {1.0});
  for (const auto& st : k.strikes) {
    EXPECT_NE(st.contact.shape, ForceShape::impulse);
    EXPECT_LE(st.contact.duration_s, 1.5e-3 + 1e-12);
    EXPECT_GE(st.contact.duration_s, 1.5e-3 * std::pow(10.0, -0.5 * 23.0 / 20.0));
  }
  EXPECT_THROW(generate_independent_case(1, {"room"}, {0.5}), std::invalid_argument);
  EXPECT_THROW(generate_independent_case(1, {"noise_floor"}, {1.5}), std::invalid_argument);
}

// Every mode's amplitude in every strike read back from the recording (least squares on the known
// frequencies and decays over the first 0.4 s), less the strike's gain and the mode's mean level.
std::vector<std::vector<double>> amplitude_residual_db(const IndependentCase& c) {
  std::vector<std::vector<double>> table;
  for (std::size_t s = 0; s < c.strikes.size(); ++s) {
    const auto& modes = c.strikes[s].modes;
    const std::size_t pre = c.strikes[s].pre_roll_frames, len = std::size_t(0.4 * kFs);
    Eigen::MatrixXd a(len, 2 * modes.size());
    Eigen::VectorXd b(len);
    for (std::size_t i = 0; i < len; ++i) {
      const double t = double(i) / kFs;
      for (std::size_t n = 0; n < modes.size(); ++n) {
        const cd z = std::exp(cd(-modes[n].decay_per_s, 2.0 * std::numbers::pi * modes[n].freq_hz) * t);
        a(i, 2 * n) = z.imag();
        a(i, 2 * n + 1) = z.real();
      }
      b(i) = c.recordings[s].samples[pre + i];
    }
    const Eigen::VectorXd x = a.colPivHouseholderQr().solve(b);
    std::vector<double> row;
    for (std::size_t n = 0; n < modes.size(); ++n)
      row.push_back(20.0 * std::log10(std::hypot(x(2 * n), x(2 * n + 1))) - c.strikes[s].gain_db);
    table.push_back(row);
  }
  for (std::size_t n = 0; n < table[0].size(); ++n) {
    double mean = 0.0;
    for (const auto& row : table) mean += row[n] / double(table.size());
    for (auto& row : table) row[n] -= mean;
  }
  return table;
}

double pooled_sd_db(const std::vector<std::vector<double>>& table) {
  double ss = 0.0;
  for (const auto& row : table)
    for (double v : row) ss += v * v;
  const double dof = double(table[0].size()) * double(table.size() - 1);  // a mean per mode
  return std::sqrt(ss / dof);
}

TEST(IndependentPhysics, AmplitudeJitterReadBackFromTheRecordings) {
  // Pooled over clean cases, the strike-to-strike scatter of a mode's level beyond the gain is the jitter.
  for (std::uint64_t seed : {600u, 601u, 602u}) {
    const IndependentCase c = generate_independent_case(seed, {}, {});
    const double sd = pooled_sd_db(amplitude_residual_db(c));
    EXPECT_NEAR(sd, c.jitter_db, 0.15 * c.jitter_db) << c.summary;
    // Struck at points spread over the region, the same object's modes move by several dB more (seeds
    // 600-602: 3.4-4.5 dB of standard deviation beyond the jitter at the weakest, 4.7-6.9 at u = 0.5).
    const IndependentCase h = generate_independent_case(seed, {"hit_position"}, {0.5});
    const double sd_hit = pooled_sd_db(amplitude_residual_db(h));
    const IndependentCase h0 = generate_independent_case(seed, {"hit_position"}, {0.0});
    const double sd_weakest = pooled_sd_db(amplitude_residual_db(h0));
    EXPECT_GT(std::sqrt(sd_weakest * sd_weakest - sd * sd), 2.0) << h0.summary;
    EXPECT_GT(std::sqrt(sd_hit * sd_hit - sd * sd), 3.0) << h.summary;
  }
}

TEST(IndependentPhysics, NoiseFloorAndHandDampingAsDrawn) {
  const IndependentCase c = generate_independent_case(610, {"noise_floor", "support_damping"}, {0.5, 0.5});
  double strongest = 0.0, energy = 0.0;
  std::size_t samples = 0;
  for (std::size_t s = 0; s < c.strikes.size(); ++s) {
    for (const auto& m : c.strikes[s].modes) strongest = std::max(strongest, std::abs(m.amp));
    for (std::size_t i = 0; i < c.strikes[s].pre_roll_frames; ++i) energy += std::pow(double(c.recordings[s].samples[i]), 2);
    samples += c.strikes[s].pre_roll_frames;
  }
  EXPECT_NEAR(c.noise_below_db, 50.0, 1e-12);
  EXPECT_NEAR(20.0 * std::log10(strongest / std::sqrt(energy / double(samples))), 50.0, 1.5);
  // The hand only adds decay, by a different amount in each strike.
  const IndependentCase clean = generate_independent_case(610, {"noise_floor"}, {0.5});
  double lowest = 1e9, highest = 0.0;  // per strike, the mean extra decay over the modes
  for (std::size_t s = 0; s < c.strikes.size(); ++s) {
    double mean = 0.0;
    for (std::size_t n = 0; n < c.object.size(); ++n) {
      const double extra = c.strikes[s].modes[n].decay_per_s - clean.strikes[s].modes[n].decay_per_s;
      EXPECT_GE(extra, 0.0);
      mean += extra / double(c.object.size());
    }
    lowest = std::min(lowest, mean);
    highest = std::max(highest, mean);
  }
  EXPECT_GT(highest, 1.5 * lowest);
}

}  // namespace
}  // namespace ms::indep
