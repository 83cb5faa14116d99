// The whole material estimate of a 2 s recording at 44.1 kHz (Ren's glass on the reference bar,
// rendered by the project, its modes extracted), all starts, on one thread:
//   Estimate/Fast        estimate_material: candidates rendered by the resonator bank, loudness
//                        images through one FFTW plan;
//   Evaluation/Fast      one candidate's score as the search computes it;
//   Evaluation/Naive     the same score with the candidate rendered by the exact reference renderer
//                        (exp and sin per sample per mode, double), the naive cost of every one of the
//                        search's evaluations (a whole naive estimate would take evaluations x this).
// Counters: per_start_s (the estimate's time over its starts) beside the patent's 46.5 s (wood) to
// 393.5 s (metal) per start (US 9,401,684 Table II, one 2.8 GHz core), and the evaluations per estimate.
#include <benchmark/benchmark.h>

#include "analysis/estimation/estimate_material.hpp"
#include "analysis/extraction/feature_extraction.hpp"
#include "synthesis/material.hpp"
#include "synthesis/reference_objects.hpp"
#include "synthesis/reference_renderer.hpp"

namespace {

constexpr double kFs = 44100.0;

struct Case {
  ms::ObjectEigen bar;
  ms::Candidate truth;
  std::vector<float> recording;
  std::vector<ms::Mode> modes;
};

const Case& glass_bar() {
  static const Case c = [] {
    Case k;
    const ms::ObjectModes om = ms::free_free_bar(0.25, 0.012, {0.1}, 1e12, 30);
    k.bar = {om.lambda0, om.gains[0], {}};
    const ms::Material& m = *ms::find_material("ren2013/glass");
    k.truth = {m.rayleigh.alpha1, m.rayleigh.alpha2, m.specific_modulus_m2_s2, 0.01};
    k.recording = ms::render_candidate(ms::candidate_model(k.bar, k.truth, kFs / 2), {}, kFs, std::size_t(2 * kFs));
    k.modes = ms::extract_features(k.recording, kFs).modes;
    return k;
  }();
  return c;
}

void BM_Estimate_Fast(benchmark::State& state) {
  const Case& c = glass_bar();
  std::size_t starts = 0, evaluations = 0;
  for (auto _ : state) {
    const ms::MaterialEstimate e = ms::estimate_material(c.recording, kFs, c.modes, c.bar, {});
    starts = e.starts.size();
    evaluations = 0;
    for (const auto& s : e.starts) evaluations += s.evaluations;
    benchmark::DoNotOptimize(e.material.gamma);
  }
  state.counters["starts"] = double(starts);
  state.counters["evaluations_in_searches"] = double(evaluations);
  state.counters["per_start_s"] = benchmark::Counter(double(state.iterations()) * double(starts),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["patent_per_start_s_wood"] = 46.5;
  state.counters["patent_per_start_s_metal"] = 393.5;
}
BENCHMARK(BM_Estimate_Fast)->Unit(benchmark::kSecond)->Iterations(1);

template <bool kNaive>
void BM_Evaluation(benchmark::State& state) {
  const Case& c = glass_bar();
  const ms::PerceptualReference ref(c.recording, kFs, c.modes);
  const ms::ModalModel model = ms::candidate_model(c.bar, c.truth, kFs / 2);
  for (auto _ : state) {
    std::vector<float> y;
    if constexpr (kNaive) {
      const std::vector<double> exact = ms::render_reference(model, {}, kFs, c.recording.size());
      y.assign(exact.begin(), exact.end());
    } else {
      y = ms::render_candidate(model, {}, kFs, c.recording.size());
    }
    benchmark::DoNotOptimize(ref.compare(y, model.modes).hybrid);
  }
}
BENCHMARK_TEMPLATE(BM_Evaluation, false)->Name("Evaluation/Fast")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Evaluation, true)->Name("Evaluation/Naive")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
