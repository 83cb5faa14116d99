// Pi_hybrid between two 2 s recordings at 44.1 kHz (40 modes each, 50 Hz - 12 kHz log-uniform, decays
// 2-80 1/s, amps 1e-3 - 0.2, seeds 1 and 2), as the estimation evaluates it:
//   Fast/EstimateOnly  the reference's image and features made once, then per evaluation the other
//                      sound's loudness image (FFTW plan reused, contours folded per band), its
//                      modes' weights and the match ratio product;
//   Fast/BothSounds    both images and both feature sets per evaluation;
//   Naive/BothSounds   the same with a per-frame direct DFT (twiddle table, no FFT) and the ISO 226
//                      contour interpolated and evaluated afresh for every pixel.
// The counter rel_diff is |Pi_hybrid naive - fast| / Pi_hybrid fast (the two must agree).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>

#include "analysis/estimation/iso226_loudness.hpp"
#include "analysis/estimation/perceptual_metric.hpp"
#include "synthesis/bark.hpp"
#include "synthesis/reference_renderer.hpp"

namespace {

constexpr double kFs = 44100.0;

struct Sound {
  std::vector<ms::Mode> modes;
  std::vector<float> samples;
};

Sound random_sound(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> logf(std::log(50.0), std::log(12000.0)), decay(2.0, 80.0),
      loga(std::log(1e-3), std::log(0.2));
  Sound s;
  ms::ModalModel m;
  for (int i = 0; i < 40; ++i) m.modes.push_back({std::exp(logf(rng)), decay(rng), std::exp(loga(rng)), 0.0});
  const auto y = ms::render_reference(m, {}, kFs, std::size_t(2.0 * kFs));
  s.samples.assign(y.begin(), y.end());
  s.modes = m.modes;
  return s;
}

const Sound& sound_a() {
  static const Sound s = random_sound(1);
  return s;
}
const Sound& sound_b() {
  static const Sound s = random_sound(2);
  return s;
}

// The naive loudness image: same grid, direct DFT per frame, contour per pixel.
ms::BarkImage naive_power(const std::vector<float>& x, const ms::LoudnessImager& grid) {
  const std::size_t n = grid.window(), hop = grid.hop();
  std::vector<double> cosine(n), sine(n);
  for (std::size_t i = 0; i < n; ++i) {
    cosine[i] = std::cos(2.0 * std::numbers::pi * double(i) / double(n));
    sine[i] = std::sin(2.0 * std::numbers::pi * double(i) / double(n));
  }
  const std::vector<double>& w = grid.window_samples();
  double w2 = 0.0;
  for (double v : w) w2 += v * v;
  ms::BarkImage img;
  img.bands = grid.bands();
  img.hop_s = double(hop) / kFs;
  img.band_bark = grid.band_bark();
  img.frames = x.size() < n ? 1 : (x.size() - n) / hop + 1;
  img.cells.assign(img.frames * img.bands, 0.0);
  std::vector<double> frame(n);
  for (std::size_t m = 0; m < img.frames; ++m) {
    for (std::size_t i = 0; i < n; ++i) frame[i] = m * hop + i < x.size() ? w[i] * double(x[m * hop + i]) : 0.0;
    for (std::size_t k = 1; k <= n / 2; ++k) {
      double re = 0.0, im = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        re += frame[i] * cosine[(k * i) % n];
        im -= frame[i] * sine[(k * i) % n];
      }
      const std::size_t band = std::min(grid.bands() - 1, grid.band_of_hz(double(k) * kFs / double(n)));
      img.at(m, band) += (k == n / 2 ? 1.0 : 2.0) * (re * re + im * im) / (double(n) * w2);
    }
  }
  return img;
}

ms::BarkImage naive_loudness(const ms::BarkImage& power, const ms::LoudnessImager& grid, double cal) {
  ms::BarkImage img = power;
  for (std::size_t m = 0; m < img.frames; ++m)
    for (std::size_t b = 0; b < img.bands; ++b) {
      const double p = power.at(m, b);
      const ms::Iso226Row row = ms::iso226_parameters(grid.band_centre_hz(b));
      img.at(m, b) = p > 0.0 ? ms::sone_from_phon(ms::iso226_loudness_phon(row, cal + 10.0 * std::log10(p))) : 0.0;
    }
  return img;
}

struct NaiveScores {
  double psycho, hybrid;
};

NaiveScores naive_hybrid(const Sound& a, const Sound& b, const ms::LoudnessImager& grid) {
  const ms::BarkImage pa = naive_power(a.samples, grid), pb = naive_power(b.samples, grid);
  const double cal = ms::db_spl_at_unit_power_for_peak(pa, 70.0);
  const ms::BarkImage sa = naive_loudness(pa, grid, cal), sb = naive_loudness(pb, grid, cal);
  const double psycho = ms::psycho_distance(sa, sb);
  const auto fa = ms::loudness_weighted_features(a.modes, grid, cal, sa.frames);
  const auto fb = ms::loudness_weighted_features(b.modes, grid, cal, sa.frames);
  return {psycho, ms::hybrid_metric(psycho, ms::match_ratio_product(fa, fb))};
}

void BM_HybridFastEstimateOnly(benchmark::State& state) {
  const ms::PerceptualReference ref(sound_a().samples, kFs, sound_a().modes);
  double h = 0.0;
  for (auto _ : state) {
    const double v = ref.compare(sound_b().samples, sound_b().modes).hybrid;
    benchmark::DoNotOptimize(v);
    h = v;
  }
  state.counters["hybrid"] = h;
}

void BM_HybridFastBothSounds(benchmark::State& state) {
  double h = 0.0;
  for (auto _ : state) {
    const ms::PerceptualReference ref(sound_a().samples, kFs, sound_a().modes);
    const double v = ref.compare(sound_b().samples, sound_b().modes).hybrid;
    benchmark::DoNotOptimize(v);
    h = v;
  }
  state.counters["hybrid"] = h;
}

void BM_HybridNaiveBothSounds(benchmark::State& state) {
  const ms::LoudnessImager grid(kFs);
  NaiveScores s{};
  for (auto _ : state) {
    s = naive_hybrid(sound_a(), sound_b(), grid);
    benchmark::DoNotOptimize(s);
  }
  const ms::PerceptualReference ref(sound_a().samples, kFs, sound_a().modes);
  const double fast = ref.compare(sound_b().samples, sound_b().modes).hybrid;
  state.counters["hybrid"] = s.hybrid;
  state.counters["rel_diff"] = std::abs(s.hybrid - fast) / fast;
}

}  // namespace

BENCHMARK(BM_HybridFastEstimateOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HybridFastBothSounds)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HybridNaiveBothSounds)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
