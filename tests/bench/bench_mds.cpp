// Metric SMACOF speed on the 100 x 100 matrix of tests/data/mds/sklearn_compare.py, with the options
// `modalstudy stats mds --method smacof` uses (classical start + 3 seeded random starts, i.e. as many
// starts as scikit-learn's n_init = 4). tests/bench/mds_vs_sklearn.sh times scikit-learn's fit
// on the same matrix in the same run and prints the ratio. The matrix path is taken from the
// environment variable MDS_MATRIX, else the source tree's copy.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>

#include "analysis/stats/dissimilarity_matrix.hpp"
#include "analysis/stats/mds.hpp"
#include "synthesis/tidy_csv.hpp"

namespace {

const ms::DissimilarityMatrix& matrix() {
  static const ms::DissimilarityMatrix m = [] {
    const char* env = std::getenv("MDS_MATRIX");
    const std::string path = env ? env : std::string(MODALSTUDY_TEST_DATA) + "/mds/sklearn_matrix.csv";
    return ms::dissimilarity_from_square(ms::TidyCsv::read(path));
  }();
  return m;
}

void BM_SmacofDefaultStarts(benchmark::State& state) {
  const ms::DissimilarityMatrix& d = matrix();
  ms::SmacofOptions o;  // CLI defaults
  double stress1 = 0;
  int iterations = 0;
  for (auto _ : state) {
    const ms::SmacofResult r = ms::smacof(d.values, o);
    benchmark::DoNotOptimize(r.points.data());
    stress1 = r.stress1;
    iterations = r.iterations;
  }
  state.counters["n"] = double(d.labels.size());
  state.counters["starts"] = o.random_starts + 1;
  state.counters["stress1"] = stress1;
  state.counters["iterations_best"] = iterations;
}
BENCHMARK(BM_SmacofDefaultStarts)->Unit(benchmark::kMillisecond);

void BM_ClassicalOnly(benchmark::State& state) {
  const ms::DissimilarityMatrix& d = matrix();
  for (auto _ : state) benchmark::DoNotOptimize(ms::classical_mds(d.values, 2).points.data());
}
BENCHMARK(BM_ClassicalOnly)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
