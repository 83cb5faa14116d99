// Repeated-measures ANOVA speed on the 2019 design (24 listeners x 5 x 2 x 4 = 40 cells): the Eigen
// contrast implementation (with and without building the design from a parsed CSV) against the
// textbook marginal-means loops over the long data (naive_anova.hpp), in the same run.
#include <benchmark/benchmark.h>

#include <random>
#include <string>

#include "../support/naive_anova.hpp"
#include "analysis/stats/rm_anova.hpp"
#include "analysis/stats/rm_data.hpp"
#include "synthesis/tidy_csv.hpp"

namespace {

struct Study {
  std::string csv;
  std::vector<ms::test::LongRow> rows;
};

const Study& study() {
  static const Study s = [] {
    Study st;
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(0.0, 1.0);
    st.csv = "listener,material,shape,dataset,rating\n";
    for (int l = 0; l < 24; ++l)
      for (int m = 0; m < 5; ++m)
        for (int h = 0; h < 2; ++h)
          for (int d = 0; d < 4; ++d) {
            const double y = 4 + 0.5 * m + 0.3 * h + noise(rng);
            st.csv += "L" + std::to_string(l) + ",m" + std::to_string(m) + ",h" + std::to_string(h) + ",d" +
                      std::to_string(d) + "," + std::to_string(y) + "\n";
            st.rows.push_back(ms::test::LongRow{l, {m, h, d}, y});
          }
    return st;
  }();
  return s;
}

const ms::RmColumns kColumns{"rating", "listener", {"material", "shape", "dataset"}, {}};

void BM_RmAnovaEigen(benchmark::State& state) {
  const ms::TidyCsv table = ms::TidyCsv::parse(study().csv, "bench.csv");
  std::vector<std::string> notices;
  const ms::RmData data = ms::rm_data_from_table(table, kColumns, notices);
  for (auto _ : state) benchmark::DoNotOptimize(ms::rm_anova(data));
}
BENCHMARK(BM_RmAnovaEigen)->Unit(benchmark::kMicrosecond);

// Everything the CLI does after reading the file: parse, aggregate to cell means, ANOVA.
void BM_RmAnovaFromCsvText(benchmark::State& state) {
  for (auto _ : state) {
    const ms::TidyCsv table = ms::TidyCsv::parse(study().csv, "bench.csv");
    std::vector<std::string> notices;
    benchmark::DoNotOptimize(ms::rm_anova(ms::rm_data_from_table(table, kColumns, notices)));
  }
}
BENCHMARK(BM_RmAnovaFromCsvText)->Unit(benchmark::kMicrosecond);

// Reference: sums of squares per effect by passes over the long data (F only, no sphericity).
void BM_RmAnovaNaiveLoops(benchmark::State& state) {
  const auto& rows = study().rows;
  for (auto _ : state) benchmark::DoNotOptimize(ms::test::naive_within_anova(rows, {5, 2, 4}, 24));
}
BENCHMARK(BM_RmAnovaNaiveLoops)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
