// Work items 0..n-1 that stand alone (each strike's extraction, each cross-validation fold, each effect's
// detector, a room's two guesses) run on the machine's cores; a call inside an item (a room's guesses
// inside a fold) starts threads of its own, briefly more threads than cores. Each item writes only its own
// slot of the caller's output, so the results, and any sum the caller then takes over them in index order,
// do not depend on the threads. The first exception an item throws (by index) is rethrown once all have
// finished.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace ms::audit {

template <typename Work>
void parallel_indices(std::size_t n, const Work& work) {
  std::vector<std::exception_ptr> failed(n);
  std::atomic<std::size_t> next{0};
  const auto run = [&] {
    for (std::size_t i; (i = next++) < n;) {
      try {
        work(i);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    }
  };
  const std::size_t threads = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), n);
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(run);
  run();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace ms::audit
