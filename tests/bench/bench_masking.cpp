// Masking thresholds of N random modes: the fast implementation against the O(N^2) naive one, and
// the whole prune (levels, Bark, thresholds, ordering). Random modes: 50 Hz - 16 kHz log-uniform,
// decays 1-100 1/s uniform, amps 1e-4 - 1 log-uniform, seed 42; a_v 16 dB, playback 70 dB.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "synthesis/bark.hpp"
#include "synthesis/masking_pruning.hpp"

namespace {

ms::ModalModel random_modes(std::size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> logf(std::log(50.0), std::log(16000.0));
  std::uniform_real_distribution<double> decay(1.0, 100.0), loga(std::log(1e-4), 0.0);
  ms::ModalModel m;
  for (std::size_t i = 0; i < n; ++i) m.modes.push_back({std::exp(logf(rng)), decay(rng), std::exp(loga(rng)), 0.0});
  return m;
}

struct Inputs {
  std::vector<double> bark, level;
};

Inputs inputs(std::size_t n) {
  const ms::ModalModel m = random_modes(n);
  Inputs in;
  in.level = ms::mode_levels_db(ms::mode_powers(m), 70.0);
  for (const auto& md : m.modes) in.bark.push_back(ms::bark_zwicker_terhardt(md.freq_hz));
  return in;
}

template <bool kNaive, ms::MaskingCombine kCombine>
void BM_MaskingThreshold(benchmark::State& state) {
  const Inputs in = inputs(std::size_t(state.range(0)));
  for (auto _ : state) {
    auto t = kNaive ? ms::masking_threshold_db_naive(in.bark, in.level, 16.0, kCombine)
                    : ms::masking_threshold_db(in.bark, in.level, 16.0, kCombine);
    benchmark::DoNotOptimize(t.data());
  }
  state.SetComplexityN(state.range(0));
}

void BM_PruneModes(benchmark::State& state) {
  const ms::ModalModel m = random_modes(std::size_t(state.range(0)));
  ms::PruneOptions o;
  o.combine = state.range(1) ? ms::MaskingCombine::sum : ms::MaskingCombine::max;
  for (auto _ : state) {
    auto r = ms::prune_modes(m, o);
    benchmark::DoNotOptimize(r.kept.data());
  }
}

}  // namespace

BENCHMARK(BM_MaskingThreshold<false, ms::MaskingCombine::max>)->Name("fast/max")->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MaskingThreshold<true, ms::MaskingCombine::max>)->Name("naive/max")->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MaskingThreshold<false, ms::MaskingCombine::sum>)->Name("fast/sum")->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MaskingThreshold<true, ms::MaskingCombine::sum>)->Name("naive/sum")->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PruneModes)->Name("prune_modes/combine(0=max,1=sum)")->Args({10000, 0})->Args({10000, 1})->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
