// The whole material estimate of a 2 s recording at 44.1 kHz, all starts, on one thread, on the
// shipped bar and plate parameter sets' objects (Ren's glass, rendered by the project with the set's
// strike, its modes extracted; the estimator is given the strike's shape and fits its duration):
//   Estimate/bar, Estimate/plate   estimate_material with its defaults: each candidate's modes
//                        rendered only while above the floor (render_candidate_above: the contact
//                        summed once per mode, the free decays in resonator banks of 4 lengths),
//                        loudness images through one FFTW plan;
//   Estimate/plate_full_render     the same with every mode rendered over the whole recording;
//   Evaluation/Fast      one candidate's score on the bar as the search computes it (all modes);
//   Evaluation/Naive     the same score with the candidate rendered by the exact reference renderer
//                        (exp and sin per sample per mode, double), the naive cost of every one of the
//                        search's evaluations (a whole naive estimate would take evaluations x this).
// Counters: per_start_s (the estimate's time over its starts) beside the patent's 46.5 s (wood) to
// 393.5 s (metal) per start (US 9,401,684 Table II, one 2.8 GHz core), the evaluations per estimate
// (screening, refinement and polish), the object's modes and the estimate's modes below Nyquist, and
// the estimate's errors against the material rendered.
#include <benchmark/benchmark.h>

#include <string>

#include "analysis/estimation/estimate_material.hpp"
#include "analysis/extraction/feature_extraction.hpp"
#include "synthesis/material.hpp"
#include "synthesis/reference_renderer.hpp"

namespace {

constexpr double kFs = 44100.0;

struct Case {
  ms::ObjectEigen object;
  ms::Candidate truth;
  std::vector<float> recording;
  std::vector<ms::Mode> modes;
};

Case glass_on(const std::string& set) {
  Case k;
  k.object = ms::object_eigen_from_paramset(MODALSTUDY_TEST_DATA "/../../stimuli/" + set);
  const ms::Material& m = *ms::find_material("ren2013/glass");
  k.truth = {m.rayleigh.alpha1, m.rayleigh.alpha2, m.specific_modulus_m2_s2, 0.01};
  k.recording = ms::render_candidate(ms::candidate_model(k.object, k.truth, kFs / 2), k.object.strike, kFs,
                                     std::size_t(2 * kFs));
  ms::ExtractOptions extract;  // as modalstudy estimate extracts (the strike has a finite contact)
  extract.skip_contact_s = 0.5e-3;
  extract.max_attack_skip_s = 20e-3;
  k.modes = ms::extract_features(k.recording, kFs, extract).modes;
  return k;
}

const Case& glass_bar() {
  static const Case c = glass_on("bar/ren-glass.yaml");
  return c;
}
const Case& glass_plate() {
  static const Case c = glass_on("plate/ren-glass.yaml");
  return c;
}

void estimate(benchmark::State& state, const Case& c, bool full_render) {
  ms::EstimateOptions o;
  if (full_render) o.render_floor_below_quiet_db = -1.0;
  std::size_t starts = 0, evaluations = 0;
  ms::MaterialEstimate e;
  for (auto _ : state) {
    e = ms::estimate_material(c.recording, kFs, c.modes, c.object, c.object.strike, o);
    starts = e.starts.size();
    evaluations = 0;
    for (const auto& s : e.starts) evaluations += s.evaluations;
    evaluations += e.polish_evaluations;
    // A copy: DoNotOptimize on e.material.gamma itself (a read-write asm operand) left garbage in it.
    const double gamma = e.material.gamma;
    benchmark::DoNotOptimize(gamma);
  }
  state.counters["starts"] = double(starts);
  state.counters["evaluations_in_searches"] = double(evaluations);
  state.counters["gamma_error_pct"] = 100.0 * (e.material.gamma / c.truth.gamma - 1.0);
  state.counters["sigma_error_pct"] = 100.0 * (e.material.sigma / c.truth.sigma - 1.0);
  state.counters["alpha_error_pct"] = 100.0 * (e.material.alpha / c.truth.alpha - 1.0);
  state.counters["beta_error_pct"] = 100.0 * (e.material.beta / c.truth.beta - 1.0);
  state.counters["per_start_s"] = benchmark::Counter(double(state.iterations()) * double(starts),
                                                     benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["patent_per_start_s_wood"] = 46.5;
  state.counters["patent_per_start_s_metal"] = 393.5;
  state.counters["object_modes"] = double(c.object.lambda0.size());
  state.counters["material_modes"] = double(ms::candidate_model(c.object, e.material, kFs / 2).modes.size());
  state.counters["polish_evaluations"] = double(e.polish_evaluations);
}

void BM_Estimate_bar(benchmark::State& state) { estimate(state, glass_bar(), false); }
void BM_Estimate_plate(benchmark::State& state) { estimate(state, glass_plate(), false); }
void BM_Estimate_plate_full_render(benchmark::State& state) { estimate(state, glass_plate(), true); }
BENCHMARK(BM_Estimate_bar)->Name("Estimate/bar")->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Estimate_plate)->Name("Estimate/plate")->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_Estimate_plate_full_render)->Name("Estimate/plate_full_render")->Unit(benchmark::kSecond)->Iterations(1);

template <bool kNaive>
void BM_Evaluation(benchmark::State& state) {
  const Case& c = glass_bar();
  const ms::PerceptualReference ref(c.recording, kFs, c.modes);
  const ms::ModalModel model = ms::candidate_model(c.object, c.truth, kFs / 2);
  for (auto _ : state) {
    std::vector<float> y;
    if constexpr (kNaive) {
      const std::vector<double> exact = ms::render_reference(model, c.object.strike, kFs, c.recording.size());
      y.assign(exact.begin(), exact.end());
    } else {
      y = ms::render_candidate(model, c.object.strike, kFs, c.recording.size());
    }
    benchmark::DoNotOptimize(ref.compare(y, model.modes).hybrid);
  }
}
BENCHMARK_TEMPLATE(BM_Evaluation, false)->Name("Evaluation/Fast")->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Evaluation, true)->Name("Evaluation/Naive")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
