// FFTW's planner (plan creation and destruction) is not thread-safe; the core renders and analyses
// stimuli on worker threads, so every plan made here is made under this one lock.
#pragma once
#include <mutex>

namespace ms {

inline std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace ms
