// The room response: its per-band decay (Schroeder backward integration of each octave band), its
// direct-to-reverberant ratio, its FFT convolution against a direct sum, and effects.room through the
// parameter-set codec and the renderer.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>

#include "synthesis/fft.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/paramset_recipe.hpp"
#include "synthesis/room_response.hpp"
#include "synthesis/stimulus.hpp"

using namespace ms;

namespace {

constexpr double kFs = 44100.0;

// The reverberant part of h (h[1..]) restricted to [lo, hi) Hz by a mask on its spectrum, its edges
// raised-cosine tapers a sixth of an octave wide outside the band (a brick wall's sinc would smear the
// early energy into the late decay).
std::vector<double> band_of(const std::vector<float>& h, double lo, double hi) {
  RealFft fft(nice_fft_size(2 * h.size()), RealFft::Directions::forward_and_backward);
  const std::size_t n = fft.size();
  std::fill(fft.real(), fft.real() + n, 0.0);
  for (std::size_t i = 1; i < h.size(); ++i) fft.real()[i - 1] = h[i];
  fft.forward();
  for (std::size_t k = 0; k <= n / 2; ++k) {
    const double f = double(k) * kFs / double(n);
    const double taper = std::pow(2.0, 1.0 / 6), lo_out = lo / taper, hi_out = hi * taper;
    double w = f >= lo && f < hi ? 1.0 : 0.0;
    if (f >= lo_out && f < lo) w = 0.5 - 0.5 * std::cos(M_PI * std::log(f / lo_out) / std::log(taper));
    if (f >= hi && f < hi_out) w = 0.5 + 0.5 * std::cos(M_PI * std::log(f / hi) / std::log(taper));
    fft.spectrum()[k] *= w;
  }
  fft.backward();
  return std::vector<double>(fft.real(), fft.real() + h.size() - 1);
}

// RT60 from the Schroeder curve's slope between -5 and -25 dB (T20, least squares).
double schroeder_rt60_s(const std::vector<double>& x) {
  std::vector<double> edc(x.size());
  double acc = 0.0;
  for (std::size_t i = x.size(); i-- > 0;) edc[i] = acc += x[i] * x[i];
  double st = 0, sy = 0, stt = 0, sty = 0, n = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double db = 10.0 * std::log10(edc[i] / edc[0]);
    if (db > -5.0 || db < -25.0) continue;
    const double t = double(i) / kFs;
    st += t, sy += db, stt += t * t, sty += t * db, n += 1;
  }
  const double slope = (n * sty - st * sy) / (n * stt - st * st);
  return -60.0 / slope;
}

Room room(std::vector<double> rt60_s, double drr_db, std::uint64_t seed) {
  return {.rt60_s = std::move(rt60_s), .drr_db = drr_db, .seed = seed, .enabled = true};
}

}  // namespace

// One draw's T20 in a low octave (~100 Hz wide over ~0.3 s) scatters by ~10 %: the mean over seeds is checked.
constexpr std::uint64_t kSeeds = 8;

TEST(RoomResponse, EachOctaveBandDecaysAtItsRt60) {
  const std::vector<double> asked{1.0, 0.9, 0.8, 0.7, 0.55, 0.45, 0.3};
  std::vector<double> mean(asked.size(), 0.0);
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const std::vector<float> h = room_impulse_response(room(asked, 3.0, seed), kFs);
    for (std::size_t b = 0; b < asked.size(); ++b) {
      // The band's inner two thirds of an octave (away from its neighbours' edges), and 63 Hz up for the lowest.
      const double c = kRoomOctaveCentresHz[b];
      mean[b] += schroeder_rt60_s(band_of(h, b == 0 ? 63.0 : c / std::pow(2.0, 1.0 / 3), c * std::pow(2.0, 1.0 / 3))) / kSeeds;
    }
  }
  for (std::size_t b = 0; b < asked.size(); ++b)
    EXPECT_NEAR(mean[b], asked[b], 0.05 * asked[b]) << "band " << kRoomOctaveCentresHz[b] << " Hz";
}

TEST(RoomResponse, OneRt60ServesEveryBand) {
  EXPECT_EQ(room_impulse_response(room({0.5}, 0.0, 3), kFs).size(), std::size_t(std::ceil(0.5 * kFs)) + 1);
  for (double c : {250.0, 1000.0, 4000.0}) {
    double mean = 0.0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed)
      mean += schroeder_rt60_s(band_of(room_impulse_response(room({0.5}, 0.0, seed), kFs), c / std::sqrt(2.0),
                                       c * std::sqrt(2.0))) / kSeeds;
    EXPECT_NEAR(mean, 0.5, 0.025) << c;
  }
}

TEST(RoomResponse, DirectToReverberantRatioIsAsAsked) {
  for (double drr : {-2.0, 3.0, 8.0}) {
    const std::vector<float> h = room_impulse_response(room({0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9}, drr, 11), kFs);
    double tail = 0.0;
    for (std::size_t i = 1; i < h.size(); ++i) tail += double(h[i]) * h[i];
    EXPECT_NEAR(10.0 * std::log10(double(h[0]) * h[0] / tail), drr, 1e-4);
  }
}

TEST(RoomResponse, SeedsDrawDifferentTailsAndRepeat) {
  const Room a = room({0.4}, 2.0, 1), b = room({0.4}, 2.0, 2);
  EXPECT_EQ(room_impulse_response(a, kFs), room_impulse_response(a, kFs));
  EXPECT_NE(room_impulse_response(a, kFs), room_impulse_response(b, kFs));
}

TEST(RoomResponse, OverlapAddEqualsDirectConvolution) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  // Signals shorter than, about as long as, and many blocks longer than the response.
  for (std::size_t len : {std::size_t(100), std::size_t(3000), std::size_t(20000)}) {
    std::vector<float> x(len), ir(2500);
    for (float& v : x) v = float(g(rng));
    for (float& v : ir) v = float(g(rng) * 0.1);
    std::vector<float> y = x;
    convolve_overlap_add(y, ir);
    ASSERT_EQ(y.size(), x.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < len; ++i) {
      double direct = 0.0;
      for (std::size_t k = 0; k < ir.size() && k <= i; ++k) direct += double(ir[k]) * x[i - k];
      worst = std::max(worst, std::abs(direct - y[i]));
    }
    EXPECT_LT(worst, 1e-4) << len;
  }
}

TEST(RoomResponse, BandsCoverEveryFrequencyOnce) {
  EXPECT_EQ(room_octave_band(0.0), 0u);
  EXPECT_EQ(room_octave_band(1000.0), 3u);
  EXPECT_EQ(room_octave_band(20000.0), kRoomOctaveCentresHz.size() - 1);
  for (std::size_t b = 0; b + 1 < kRoomOctaveCentresHz.size(); ++b) {
    EXPECT_EQ(room_octave_upper_edge_hz(b), room_octave_lower_edge_hz(b + 1));
    EXPECT_EQ(room_octave_band(room_octave_upper_edge_hz(b)), b + 1);
  }
}

namespace {

const std::string kSet = "duration_s: 1\nmodes: [{freq_hz: 440, decay_per_s: 30, amp: 1}]\n";

std::string error_of(const std::string& text) {
  try {
    resolve(read_recipe(text, "set.yaml", "."));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RoomResponse, ParameterSetsReadWriteAndRenderTheRoom) {
  for (const std::string room_yaml : {"{rt60_s: 0.6, drr_db: 4, seed: 9}",
                                      "{rt60_s: [1, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4], drr_db: -2, seed: 9}"}) {
    const ParamSetRecipe r = read_recipe(kSet + "effects: {room: " + room_yaml + "}\n", "set.yaml", ".");
    ASSERT_TRUE(r.room.enabled);
    const std::string yaml = write_yaml(r);
    const ParamSetRecipe again = read_recipe(yaml, "written.yaml", ".");
    EXPECT_EQ(write_yaml(again), yaml);
    EXPECT_EQ(again.room.rt60_s, r.room.rt60_s);
    EXPECT_EQ(again.room.drr_db, r.room.drr_db);
    EXPECT_EQ(again.room.seed, r.room.seed);
    EXPECT_EQ(resolve(again).recipe_hash, resolve(r).recipe_hash);
    // The rendering is the dry rendering convolved with the room's response (before the output level).
    const ParamSet wet = resolve(r);
    ParamSet dry = wet;
    dry.room = {};
    const RenderedStimulus w = render_stimulus(wet), d = render_stimulus(dry);
    std::vector<float> expected = d.audio.samples;
    for (float& v : expected) v = float(v / d.level_gain);
    convolve_overlap_add(expected, room_impulse_response(wet.room, wet.sample_rate_hz));
    double worst = 0.0;
    for (std::size_t i = 0; i < expected.size(); ++i)
      worst = std::max(worst, std::abs(double(expected[i]) * w.level_gain - w.audio.samples[i]));
    EXPECT_LT(worst, 1e-5);
  }
  EXPECT_NE(resolve(read_recipe(kSet + "effects: {room: {rt60_s: 0.6, drr_db: 4, seed: 1}}\n", "a", ".")).recipe_hash,
            resolve(read_recipe(kSet + "effects: {room: {rt60_s: 0.6, drr_db: 4, seed: 2}}\n", "a", ".")).recipe_hash);
}

TEST(RoomResponse, BadRoomKeysAreLocated) {
  const auto err = [](const std::string& room_yaml) { return error_of(kSet + "effects:\n  room: " + room_yaml + "\n"); };
  EXPECT_NE(err("{rt60_s: [0.5, 0.4], drr_db: 1}").find("set.yaml:4:"), std::string::npos);
  EXPECT_NE(err("{rt60_s: [0.5, 0.4], drr_db: 1}").find("7 values"), std::string::npos);
  EXPECT_NE(err("{rt60_s: 12, drr_db: 1}").find("(0, 10] s"), std::string::npos);
  EXPECT_NE(err("{rt60_s: [1, 1, 1, 0, 1, 1, 1], drr_db: 1}").find("effects.room.rt60_s"), std::string::npos);
  EXPECT_NE(err("{rt60_s: 0.5, drr_db: 99}").find("[-40, 60] dB"), std::string::npos);
  EXPECT_NE(err("{rt60_s: 0.5}").find("needs 'drr_db'"), std::string::npos);
  EXPECT_NE(err("{rt60_s: 0.5, drr_db: 1, rt: 2}").find("effects.room"), std::string::npos);
}
