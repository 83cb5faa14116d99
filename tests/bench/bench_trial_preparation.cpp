// The study app's speed bars, measured cold (nothing cached):
//  - preparing a 12-stimulus MUSHRA trial (2 s, 200 modes each; reference + 9 conditions + the 3.5
//    and 7 kHz anchors) through StimulusCache, <= 200 ms; beside it the same 12 stimuli rendered
//    with the closed-form reference renderer (the naive way to synthesise, double precision);
//  - an `adjust` slider move on the demo's Rayleigh steel bar, re-synthesised, <= 50 ms.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/reference_renderer.hpp"

namespace {

namespace fs = std::filesystem;

// 12 stimuli: 10 parameter sets of 200 random modes (2 s) and the two derived anchors of the first.
std::string write_mushra_protocol(const fs::path& dir) {
  fs::create_directories(dir / "sets");
  std::mt19937_64 rng(2002);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::string stimuli, conditions;
  for (int s = 0; s < 10; ++s) {
    std::ofstream set(dir / "sets" / ("s" + std::to_string(s) + ".yaml"));
    set << "sample_rate: 44100\nduration_s: 2.0\nexcitation: {type: impulse}\nlevel: {normalize: peak}\nmodes:\n";
    for (int m = 0; m < 200; ++m)
      set << "  - {freq_hz: " << 60.0 * std::pow(250.0, u(rng)) << ", decay_per_s: " << 1.0 + 60.0 * u(rng)
          << ", amp: " << u(rng) << "}\n";
    stimuli += "  s" + std::to_string(s) + ": {paramset: sets/s" + std::to_string(s) + ".yaml}\n";
    if (s > 0) conditions += std::string(conditions.empty() ? "" : ", ") + "s" + std::to_string(s);
  }
  const fs::path p = dir / "mushra.yaml";
  std::ofstream(p) << "study: bench\nsample_rate: 44100\nstimuli:\n" << stimuli
                   << "blocks:\n  - {type: mushra, reference: s0, conditions: [" << conditions << "], anchors: auto}\n";
  return p.string();
}

struct Fixture {
  fs::path dir = fs::temp_directory_path() / ("bench_trial_" + std::to_string(::getpid()));
  ms::Protocol protocol;
  Fixture() { protocol = ms::load_protocol(write_mushra_protocol(dir)); }
  ~Fixture() { fs::remove_all(dir); }
};

void BM_PrepareMushraTrial(benchmark::State& state) {
  Fixture f;
  for (auto _ : state) {
    ms::StimulusCache cache(f.protocol, "");  // cold: parameter sets loaded, every stimulus rendered
    std::size_t frames = 0;
    for (const auto& s : f.protocol.stimuli) frames += cache.samples(s.name)->size();
    benchmark::DoNotOptimize(frames);
  }
  state.counters["stimuli"] = double(f.protocol.stimuli.size());
}
BENCHMARK(BM_PrepareMushraTrial)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_PrepareMushraTrialClosedForm(benchmark::State& state) {
  Fixture f;
  std::vector<ms::ParamSet> sets;
  for (const auto& s : f.protocol.stimuli)
    if (s.kind == ms::StimulusKind::paramset) sets.push_back(ms::load_paramset(ms::resolve_protocol_path(f.protocol, s.path)));
  for (auto _ : state) {
    std::size_t frames = 0;
    for (int k = 0; k < 12; ++k) {  // 12 renders, as many as the trial's stimuli
      const auto& p = sets[std::size_t(k) % sets.size()];
      frames += ms::render_reference(p.model, p.excitation, p.sample_rate_hz, std::size_t(p.duration_s * p.sample_rate_hz)).size();
    }
    benchmark::DoNotOptimize(frames);
  }
}
BENCHMARK(BM_PrepareMushraTrialClosedForm)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_AdjustSliderMove(benchmark::State& state) {
  const ms::Protocol demo = ms::load_protocol(std::string(MODALSTUDY_TEST_DATA) + "/../../protocols/demo.yaml");
  ms::StimulusCache cache(demo, "");
  double alpha = 0.5;
  for (auto _ : state) {
    alpha += 0.001;  // every move a new recipe: a cache miss, as a real slider drag gives
    const auto s = cache.samples_with("metal-rayleigh", {"damping.alpha1=" + std::to_string(alpha)});
    benchmark::DoNotOptimize(s->data());
  }
}
BENCHMARK(BM_AdjustSliderMove)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
