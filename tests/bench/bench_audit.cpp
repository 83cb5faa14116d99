// Audit speed: 10 strikes x 2 s (the bar: <= 10 s), hidden support damping + noise floor, and
// the parts: feature extraction of all strikes and the repeatability floor vs the audit proper. A reference variant runs the
// cross-validation naively (every fold re-extracts the training strikes' features from audio).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "analysis/audit/audit.hpp"
#include "analysis/audit/hidden_effect_generator.hpp"
#include "analysis/audit/repeatability_floor.hpp"

namespace {

ms::audit::HiddenCase ten_strikes(const std::vector<std::string>& effects = {"support_damping", "noise_floor"}) {
  ms::audit::GeneratorOptions g;
  g.strikes = 10;
  g.duration_s = 2.0;
  return ms::audit::generate_hidden_case(4242, effects, std::vector<double>(effects.size(), 0.5), g);
}

void BM_AuditTenStrikes(benchmark::State& state) {
  const auto hc = ten_strikes();
  for (auto _ : state) {
    const auto data = ms::audit::make_audit_data(hc.recordings);
    const auto r = ms::audit::run_audit(data);
    benchmark::DoNotOptimize(r.gap_after_db);
  }
}
BENCHMARK(BM_AuditTenStrikes)->Unit(benchmark::kMillisecond)->Iterations(3);

// The slowest kind of recording: a room tail (the extraction weighs candidates against it) and an
// attack burst (the extraction fits each strike twice, the second time from after the burst).
void BM_AuditTenStrikesReverbAndBurst(benchmark::State& state) {
  const auto hc = ten_strikes({"reverberation", "residual_transient"});
  for (auto _ : state) {
    const auto data = ms::audit::make_audit_data(hc.recordings);
    const auto r = ms::audit::run_audit(data);
    benchmark::DoNotOptimize(r.gap_after_db);
  }
}
BENCHMARK(BM_AuditTenStrikesReverbAndBurst)->Unit(benchmark::kMillisecond)->Iterations(3);

// The repeatability floor alone (one leave-one-strike-out pass of the plain model), as run_audit adds it.
void BM_RepeatabilityFloorTenStrikes(benchmark::State& state) {
  const auto data = ms::audit::make_audit_data(ten_strikes().recordings);
  for (auto _ : state) benchmark::DoNotOptimize(ms::audit::repeatability_floor(data, ms::audit::Recipe{}).floor_db);
}
BENCHMARK(BM_RepeatabilityFloorTenStrikes)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_AuditTenStrikesExtractionOnly(benchmark::State& state) {
  const auto hc = ten_strikes();
  for (auto _ : state) benchmark::DoNotOptimize(ms::audit::make_audit_data(hc.recordings).tracks.size());
}
BENCHMARK(BM_AuditTenStrikesExtractionOnly)->Unit(benchmark::kMillisecond)->Iterations(3);

// Naive reference: each of the 10 leave-one-out folds of one candidate re-analyses its 9 training
// recordings from the audio (what a script around `modalstudy extract` would do), once per candidate.
void BM_AuditNaiveRefoldExtraction(benchmark::State& state) {
  const auto hc = ten_strikes();
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t k = 0; k < hc.recordings.size(); ++k) {
      std::vector<ms::audit::Recording> train;
      for (std::size_t s = 0; s < hc.recordings.size(); ++s)
        if (s != k) train.push_back(hc.recordings[s]);
      sum += double(ms::audit::make_audit_data(train).tracks.size());
    }
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_AuditNaiveRefoldExtraction)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
