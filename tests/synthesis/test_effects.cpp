// Effects: support damping (one-sided excess decay), split doublets (beating), background noise, and
// the decaying noises of a room tail (reverb) and an attack transient (white or band-limited).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "synthesis/effects.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/paramset_recipe.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/reference_renderer.hpp"
#include "synthesis/stimulus.hpp"

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
  for (std::size_t n = 0; n < y.size(); ++n) y[n] = float(0.5 * std::sin(2 * std::numbers::pi * 440.0 * n / 44100.0));
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

namespace {
// Energy of x[from, to) (clamped to x's length).
double energy_of(const std::vector<float>& x, std::size_t from, std::size_t to) {
  double e = 0.0;
  for (std::size_t i = from; i < std::min(to, x.size()); ++i) e += double(x[i]) * x[i];
  return e;
}
std::vector<float> difference(const std::vector<float>& a, const std::vector<float>& b) {
  std::vector<float> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  return d;
}
}  // namespace

TEST(ReverbAndTransient, LevelAndDecayAreAsAskedAndSeeded) {
  const double fs = 44100.0;
  std::vector<float> y(std::size_t(2 * fs));
  for (std::size_t n = 0; n < y.size(); ++n) y[n] = float(0.5 * std::exp(-3.0 * n / fs) * std::sin(2 * std::numbers::pi * 440.0 * n / fs));
  std::vector<float> a = y, b = y;
  add_reverb_and_transient(a, fs, Reverb{0.5, -20.0, 4, true}, AttackTransient{});
  add_reverb_and_transient(b, fs, Reverb{0.5, -20.0, 4, true}, AttackTransient{});
  EXPECT_EQ(a, b);
  const std::vector<float> tail = difference(a, y);
  EXPECT_NEAR(10 * std::log10(energy_of(tail, 0, tail.size()) / energy_of(y, 0, y.size())), -20.0, 0.3);
  // 60 dB in 0.5 s: the energy of [0.25, 0.35) s lies 30 dB below that of [0, 0.1) s.
  const std::size_t t10 = std::size_t(0.1 * fs);
  EXPECT_NEAR(10 * std::log10(energy_of(tail, 0, t10) / energy_of(tail, std::size_t(0.25 * fs), std::size_t(0.25 * fs) + t10)),
              30.0, 0.6);
  std::vector<float> c = y;
  add_reverb_and_transient(c, fs, Reverb{}, AttackTransient{-10.0, 5.0, 2, true});
  const std::vector<float> burst = difference(c, y);
  EXPECT_NEAR(10 * std::log10(energy_of(burst, 0, burst.size()) / energy_of(y, 0, y.size())), -10.0, 0.5);
  EXPECT_EQ(energy_of(burst, std::size_t(0.03 * fs), burst.size()), 0.0);  // gone after 30 ms (6 x 60 dB)
}

TEST(ReverbAndTransient, ParameterSetKeysRenderChangeTheHashAndFailWithLocation) {
  const std::string base = "duration_s: 1\nmodes: [{freq_hz: 440, decay_per_s: 1, amp: 1}]\nlevel: {normalize: none}\n";
  const ParamSet plain = parse_paramset(base, "r.yaml", ".");
  const ParamSet p = parse_paramset(base + "effects: {reverb: {rt60_s: 0.8, level_db: -25, seed: 3}, "
                                           "transient: {level_db: -15, duration_ms: 4, seed: 5}}\n", "r.yaml", ".");
  EXPECT_TRUE(p.reverb.enabled);
  EXPECT_EQ(p.reverb.rt60_s, 0.8);
  EXPECT_EQ(p.reverb.level_db, -25.0);
  EXPECT_EQ(p.transient.duration_ms, 4.0);
  EXPECT_EQ(p.transient.seed, 5u);
  EXPECT_NE(p.recipe_hash, plain.recipe_hash);
  const RenderedStimulus r0 = render_stimulus(plain), r1 = render_stimulus(p);
  EXPECT_GT(energy_of(difference(r1.audio.samples, r0.audio.samples), 0, r0.audio.samples.size()), 0.0);
  auto error_of = [&](const std::string& fx) {
    try {
      parse_paramset(base + fx, "r.yaml", ".");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of("effects: {reverb: {rt60_s: -1, level_db: -20}}\n").find("r.yaml:4:28"), std::string::npos)
      << error_of("effects: {reverb: {rt60_s: -1, level_db: -20}}\n");
  EXPECT_NE(error_of("effects: {reverb: {rt60_s: 1}}\n").find("needs 'level_db'"), std::string::npos);
  EXPECT_NE(error_of("effects: {transient: {level_db: 0, duration_ms: 500}}\n").find("(0, 100] ms"), std::string::npos);
  EXPECT_NE(error_of("effects: {transient: {level_db: 0, duration: 5}}\n").find("did you mean 'duration_ms'"),
            std::string::npos);
}

TEST(ReverbAndTransient, ABandLimitedBurstKeepsItsEnergyInItsBand) {
  // A striker's click in 1-4 kHz (held 40 ms so that its spectrum is the band's): its energy relative to
  // the direct sound as asked (mean of 16 seeds), its power spectrum |H|^2 (half the mid-band density at
  // each -3 dB edge, under 2 % of the energy outside 0.5-8 kHz; by a direct DFT of its first 40 ms),
  // nothing after 240 dB of decay, and the same seed gives the same samples.
  const double fs = 44100.0;
  std::vector<float> y(std::size_t(0.5 * fs));
  for (std::size_t n = 0; n < y.size(); ++n) y[n] = float(0.5 * std::exp(-3.0 * n / fs) * std::sin(2 * std::numbers::pi * 440.0 * n / fs));
  double level_sum = 0.0, outside = 0.0, total = 0.0, at_low = 0.0, at_high = 0.0, mid = 0.0;
  const std::size_t n = std::size_t(0.04 * fs);
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    AttackTransient t{-12.0, 20.0, seed, true};
    t.low_hz = 1000.0;
    t.high_hz = 4000.0;
    t.hold_ms = 40.0;
    std::vector<float> a = y, b = y;
    add_reverb_and_transient(a, fs, Reverb{}, t);
    add_reverb_and_transient(b, fs, Reverb{}, t);
    ASSERT_EQ(a, b);
    const std::vector<float> burst = difference(a, y);
    level_sum += 10 * std::log10(energy_of(burst, 0, burst.size()) / energy_of(y, 0, y.size()));
    for (std::size_t k = 1; k < n / 2; ++k) {
      std::complex<double> x = 0.0;
      for (std::size_t i = 0; i < n; ++i) x += double(burst[i]) * std::polar(1.0, -2.0 * std::numbers::pi * double(k * i) / double(n));
      const double f = double(k) * fs / double(n), p = std::norm(x);
      total += p;
      if (f < 500.0 || f > 8000.0) outside += p;
      if (std::abs(f - 1000.0) < 80.0) at_low += p;
      if (std::abs(f - 4000.0) < 80.0) at_high += p;
      if (std::abs(f - 2000.0) < 80.0) mid += p;
    }
    EXPECT_EQ(energy_of(burst, std::size_t(0.3 * fs), burst.size()), 0.0) << seed;  // 40 ms + 240 dB by 4 x 20 ms
  }
  EXPECT_NEAR(level_sum / 16.0, -12.0, 0.5);
  EXPECT_LT(outside, 0.02 * total);
  EXPECT_NEAR(at_low / mid, 0.5, 0.15);
  EXPECT_NEAR(at_high / mid, 0.5, 0.15);
  EXPECT_NEAR(burst_band_gain2(1000.0, 1000.0, 4000.0), 0.5, 0.01);
  EXPECT_NEAR(burst_band_gain2(8000.0, 1000.0, 4000.0), 1.0 / 257.0, 1e-6);  // 24 dB per octave
  EXPECT_NEAR(band_power_share(0.0, 11025.0, fs), 0.5 * 1.0, 0.02);           // half the band, softly
  EXPECT_EQ(band_power_share(0.0, 0.0, fs), 1.0);
}

TEST(ReverbAndTransient, TheBurstsBandIsReadWrittenAndHashedOnlyWhenGiven) {
  const std::string base = "duration_s: 1\nmodes: [{freq_hz: 440, decay_per_s: 1, amp: 1}]\nlevel: {normalize: none}\n";
  const ParamSet white = parse_paramset(base + "effects: {transient: {level_db: -15, duration_ms: 4, seed: 5}}\n", "r.yaml", ".");
  const ParamSet band = parse_paramset(
      base + "effects: {transient: {level_db: -15, duration_ms: 4, band_hz: [500, 6000], seed: 5}}\n", "r.yaml", ".");
  EXPECT_FALSE(white.transient.band_limited());
  EXPECT_EQ(band.transient.low_hz, 500.0);
  EXPECT_EQ(band.transient.high_hz, 6000.0);
  EXPECT_NE(band.recipe_hash, white.recipe_hash);
  EXPECT_EQ(canonical_recipe(white).find("transient_band"), std::string::npos);  // older sets keep their hash
  const std::string written = write_yaml(read_recipe(base + "effects: {transient: {level_db: -15, duration_ms: 4, "
                                                            "band_hz: [500, 6000], seed: 5}}\n", "r.yaml", "."));
  EXPECT_NE(written.find("band_hz: [500, 6000]"), std::string::npos) << written;
  EXPECT_EQ(parse_paramset(written, "w.yaml", ".").recipe_hash, band.recipe_hash);
  for (const char* bad : {"[6000, 500]", "[500]", "[500, 30000]", "[-1, 400]"}) {
    try {
      parse_paramset(base + "effects: {transient: {level_db: -15, duration_ms: 4, band_hz: " + bad + "}}\n", "r.yaml", ".");
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("r.yaml:4:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("band_hz"), std::string::npos) << e.what();
    }
  }
}

TEST(ReverbAndTransient, AHeldBurstKeepsItsLevelForTheHoldThenDecays) {
  // Held 20 ms, then 60 dB in 10 ms: the energy of [0, 10) ms equals that of [10, 20) ms (within the
  // noise of 441 samples), [20, 30) ms holds 1 / (13.8 ln) of a held stretch, and the whole as asked.
  const double fs = 44100.0;
  std::vector<float> y(std::size_t(0.5 * fs));
  for (std::size_t n = 0; n < y.size(); ++n) y[n] = float(0.5 * std::exp(-3.0 * n / fs) * std::sin(2 * std::numbers::pi * 440.0 * n / fs));
  double level_sum = 0.0, first_sum = 0.0, second_sum = 0.0, decay_sum = 0.0;
  const std::size_t ms10 = std::size_t(0.01 * fs);
  for (std::uint64_t seed = 1; seed <= 16; ++seed) {
    for (bool band : {false, true}) {
      AttackTransient t{-12.0, 10.0, seed, true};
      t.hold_ms = 20.0;
      if (band) { t.low_hz = 1000.0; t.high_hz = 6000.0; }
      std::vector<float> a = y;
      add_reverb_and_transient(a, fs, Reverb{}, t);
      const std::vector<float> burst = difference(a, y);
      level_sum += 10 * std::log10(energy_of(burst, 0, burst.size()) / energy_of(y, 0, y.size()));
      first_sum += energy_of(burst, 0, ms10);
      second_sum += energy_of(burst, ms10, 2 * ms10);
      decay_sum += energy_of(burst, 2 * ms10, 3 * ms10);
    }
  }
  EXPECT_NEAR(level_sum / 32.0, -12.0, 0.4);
  EXPECT_NEAR(first_sum / second_sum, 1.0, 0.1);
  // 10 ms of e^{-2 k t}, k = ln(1000) / 10 ms: (1 - 1e-6) / (2 ln 1000) of a held 10 ms.
  EXPECT_NEAR(decay_sum / second_sum, 1.0 / (2.0 * std::log(1000.0)), 0.02);
  const std::string base = "duration_s: 1\nmodes: [{freq_hz: 440, decay_per_s: 1, amp: 1}]\nlevel: {normalize: none}\n";
  const ParamSet held = parse_paramset(base + "effects: {transient: {level_db: -15, duration_ms: 4, hold_ms: 6, seed: 5}}\n", "r.yaml", ".");
  EXPECT_EQ(held.transient.hold_ms, 6.0);
  const std::string written = write_yaml(read_recipe(base + "effects: {transient: {level_db: -15, duration_ms: 4, hold_ms: 6, seed: 5}}\n", "r.yaml", "."));
  EXPECT_NE(written.find("hold_ms: 6"), std::string::npos) << written;
  EXPECT_EQ(parse_paramset(written, "w.yaml", ".").recipe_hash, held.recipe_hash);
  try {
    parse_paramset(base + "effects: {transient: {level_db: -15, duration_ms: 4, hold_ms: 80}}\n", "r.yaml", ".");
    ADD_FAILURE() << "a hold of 80 ms";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hold_ms"), std::string::npos) << e.what();
  }
}
