// Residual transfer speed on a 2 s residual at 44.1 kHz (345 frames x 513 bins): the spectrogram
// transfer (Algorithm 1) to an object of 40 modes, and Griffin-Lim's 100 iterations, which the patent
// names its costliest step (it ran 10 iterations on a GPU).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "synthesis/residual_transfer.hpp"

namespace {

constexpr double kFs = 44100.0;
constexpr std::size_t kSamples = 88200;

std::vector<ms::Mode> modes(double stretch, std::size_t count) {
  std::vector<ms::Mode> out;
  for (std::size_t i = 0; i < count; ++i) {
    const double f = stretch * 180.0 * std::pow(double(i + 1), 1.6);
    if (f < 0.5 * kFs) out.push_back(ms::Mode{f, 2.0 + 1e-3 * f, 0.1 / double(i + 1), 0.0});
  }
  return out;
}

ms::ResidualSpectrogram residual() {
  ms::ResidualSpectrogram r;
  r.sample_rate_hz = kFs;
  r.frames = r.grid.frames_for(kSamples);
  r.modes = modes(1.0, 40);
  std::mt19937_64 rng(1);
  std::exponential_distribution<float> e(1.0f);
  r.power.resize(r.frames * r.grid.bins());
  for (std::size_t m = 0; m < r.frames; ++m)
    for (std::size_t k = 0; k < r.grid.bins(); ++k)
      r.power[m * r.grid.bins() + k] = e(rng) * float(std::exp(-60.0 * double(m * r.grid.hop) / kFs));
  return r;
}

void BM_TransferResidualPower(benchmark::State& state) {
  const ms::ResidualSpectrogram r = residual();
  const std::vector<ms::Mode> target = modes(1.3, 40);
  for (auto _ : state) {
    const std::vector<float> p = ms::transfer_residual_power(r, target, r.frames);
    benchmark::DoNotOptimize(p.data());
  }
}
BENCHMARK(BM_TransferResidualPower)->Unit(benchmark::kMillisecond);

void BM_GriffinLim100(benchmark::State& state) {
  const ms::ResidualSpectrogram r = residual();
  for (auto _ : state) {
    const ms::GriffinLimResult g = ms::griffin_lim(r.power, r.grid, kSamples);
    benchmark::DoNotOptimize(g.samples.data());
  }
}
BENCHMARK(BM_GriffinLim100)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
