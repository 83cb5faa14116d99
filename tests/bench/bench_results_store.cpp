// Response commit latency (required: <= 10 ms): ResultsStore::record_response (WAL, synchronous=FULL,
// one transaction) against a naive open-insert-close per response, in one run; and the same
// record_response into PostgreSQL (synchronous_commit=on) at $MODALSTUDY_TEST_POSTGRES_URL, in a schema
// of its own, dropped afterwards. The SQLite file lives in $MODALSTUDY_BENCH_DIR or the current folder
// (not /tmp: tmpfs hides fsync).
#include <benchmark/benchmark.h>
#include <sqlite3.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

#include "studyapp/core/postgres_handle.hpp"
#include "studyapp/core/results_store.hpp"

namespace {

constexpr int kTrials = 20000;

struct BenchDb {
  std::string path, schema;
  std::int64_t session = 0;
  // name "": a PostgreSQL schema (path stays "" without a server).
  explicit BenchDb(const std::string& name) {
    if (name.empty()) {
      const char* url = std::getenv("MODALSTUDY_TEST_POSTGRES_URL");
      if (!url) return;
      schema = "bench_" + std::to_string(::getpid());
      ms::pg::Connection(url).exec("CREATE SCHEMA " + schema);
      path = std::string(url) + "?options=-csearch_path%3D" + schema;
    } else {
      const char* dir = std::getenv("MODALSTUDY_BENCH_DIR");
      path = (std::filesystem::path(dir ? dir : ".") / (name + std::to_string(::getpid()) + ".sqlite")).string();
    }
    ms::ResultsStore store(path);
    store.add_study({"bench", "bench", std::string(64, '0'), "study: bench\n", false});
    session = store.start_session(store.add_participant("bench", "P", 0), 0, 1u);
    std::vector<ms::TrialRecord> trials;
    for (int i = 0; i < kTrials; ++i) trials.push_back({0, "b", "identify", i, {"s"}, {"h"}});
    store.record_trials(session, trials);
  }
  ~BenchDb() {
    if (!schema.empty()) ms::pg::Connection(std::getenv("MODALSTUDY_TEST_POSTGRES_URL")).exec("DROP SCHEMA " + schema + " CASCADE");
    if (!schema.empty()) return;
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  }
};

void record_responses(benchmark::State& state, const BenchDb& db) {
  if (db.path.empty()) {
    state.SkipWithError("MODALSTUDY_TEST_POSTGRES_URL is not set");
    return;
  }
  ms::ResultsStore store(db.path);
  int trial = 0;
  std::vector<double> latency_ms;  // the requirement is per commit, so report the tail, not only the mean
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    store.record_response(db.session, {{0, trial}, "\"metal\"", 812.5, 2, 1'700'000'000'000 + trial});
    latency_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    ++trial;
  }
  state.SetItemsProcessed(trial);
  std::sort(latency_ms.begin(), latency_ms.end());
  state.counters["p50_ms"] = latency_ms[latency_ms.size() / 2];
  state.counters["p99_ms"] = latency_ms[latency_ms.size() * 99 / 100];
  state.counters["max_ms"] = latency_ms.back();
}

void BM_RecordResponse(benchmark::State& state) { record_responses(state, BenchDb("bench_store_")); }
void BM_RecordResponsePostgres(benchmark::State& state) { record_responses(state, BenchDb("")); }

// What a first attempt often looks like: open, insert, close for every answer.
void BM_NaiveOpenInsertClose(benchmark::State& state) {
  BenchDb db("bench_naive_");
  int trial = 0;
  for (auto _ : state) {
    sqlite3* h = nullptr;
    sqlite3_open_v2(db.path.c_str(), &h, SQLITE_OPEN_READWRITE, nullptr);
    sqlite3_exec(h, "PRAGMA synchronous=FULL; PRAGMA foreign_keys=ON", nullptr, nullptr, nullptr);
    sqlite3_stmt* st = nullptr;
    sqlite3_prepare_v2(h,
                       "INSERT INTO responses(session, block_index, trial_index, value, rt_ms, plays, timestamp) "
                       "VALUES (?, 0, ?, '\"metal\"', 812.5, 2, ?)",
                       -1, &st, nullptr);
    sqlite3_bind_int64(st, 1, db.session);
    sqlite3_bind_int(st, 2, trial);
    sqlite3_bind_int64(st, 3, 1'700'000'000'000 + trial);
    if (sqlite3_step(st) != SQLITE_DONE) state.SkipWithError(sqlite3_errmsg(h));
    sqlite3_finalize(st);
    sqlite3_close(h);
    ++trial;
  }
  state.SetItemsProcessed(trial);
}

// Fixed iteration counts keep both under kTrials and make the two figures comparable.
BENCHMARK(BM_RecordResponse)->Iterations(1000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RecordResponsePostgres)->Iterations(1000)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NaiveOpenInsertClose)->Iterations(1000)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
