// Synthesis throughput in mode-samples per second: the resonator bank against a naive closed-form
// loop (exp and sin per sample per mode, double) and an STK-style biquad resonator bank, same modes.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>

#include "synthesis/resonator_bank.hpp"

using namespace ms;

namespace {

ModalModel modes(std::size_t n) {
  ModalModel m;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> logf(std::log(50.0), std::log(16000.0)), decay(0.5, 50.0), amp(0.1, 1.0);
  for (std::size_t i = 0; i < n; ++i) m.modes.push_back(Mode{std::exp(logf(rng)), decay(rng), amp(rng), 0.0});
  return m;
}

constexpr double kFs = 44100.0;
constexpr std::size_t kFrames = 44100;  // one second per iteration

void BM_ResonatorBank(benchmark::State& state) {
  const ModalModel m = modes(std::size_t(state.range(0)));
  std::vector<float> out(kFrames);
  for (auto _ : state) {
    ResonatorBank bank(m, Excitation{}, kFs);
    bank.render(out.data(), out.size());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0) * std::int64_t(kFrames));
}

// y[n] = sum a e^{-d t} sin(w t): what a first implementation does.
void BM_NaiveClosedForm(benchmark::State& state) {
  const ModalModel m = modes(std::size_t(state.range(0)));
  std::vector<double> out(kFrames);
  for (auto _ : state) {
    std::fill(out.begin(), out.end(), 0.0);
    for (const Mode& mode : m.modes) {
      const double w = 2 * std::numbers::pi * mode.freq_hz;
      for (std::size_t n = 0; n < kFrames; ++n) {
        const double t = double(n) / kFs;
        out[n] += mode.amp * std::exp(-mode.decay_per_s * t) * std::sin(w * t);
      }
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0) * std::int64_t(kFrames));
}

// STK's BiQuad (double, direct form, one filter object per mode, tick() per sample).
struct BiQuad {
  double b0 = 0, a1 = 0, a2 = 0, y1 = 0, y2 = 0, x1 = 0;
  double tick(double x) {
    const double y = b0 * x1 - a1 * y1 - a2 * y2;  // impulse-invariant resonator: b1 x[n-1]
    x1 = x;
    y2 = y1;
    y1 = y;
    return y;
  }
};

void BM_StkStyleBiquadBank(benchmark::State& state) {
  const ModalModel m = modes(std::size_t(state.range(0)));
  std::vector<double> out(kFrames);
  for (auto _ : state) {
    std::vector<BiQuad> bank(m.modes.size());
    for (std::size_t i = 0; i < bank.size(); ++i) {
      const double r = std::exp(-m.modes[i].decay_per_s / kFs), w = 2 * std::numbers::pi * m.modes[i].freq_hz / kFs;
      bank[i].a1 = -2 * r * std::cos(w);
      bank[i].a2 = r * r;
      bank[i].b0 = m.modes[i].amp * r * std::sin(w);
    }
    for (std::size_t n = 0; n < kFrames; ++n) {
      const double x = n == 0 ? 1.0 : 0.0;
      double sum = 0;
      for (auto& f : bank) sum += f.tick(x);
      out[n] = sum;
    }
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0) * std::int64_t(kFrames));
}

}  // namespace

BENCHMARK(BM_ResonatorBank)->Arg(64)->Arg(512)->Arg(4096)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NaiveClosedForm)->Arg(64)->Arg(512)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StkStyleBiquadBank)->Arg(64)->Arg(512)->Arg(4096)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
