#include "synthesis/atomic_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "synthesis/input_error.hpp"

namespace ms {

namespace fs = std::filesystem;

namespace {

// Temporaries of writes in progress, readable from a signal handler: fixed slots, no allocation.
// The one process-wide state of this file; a signal handler can reach nothing else.
constexpr std::size_t kSlots = 64, kPathBytes = 4096;
struct TempSlot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 holds a path
  char path[kPathBytes];
};
TempSlot g_temps[kSlots];

// Registers `temp`; returns the slot, or kSlots when all are taken or the path is too long (the file
// is then simply not removed on a signal).
std::size_t register_temp(const std::string& temp) {
  if (temp.size() >= kPathBytes) return kSlots;
  for (std::size_t i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!g_temps[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(g_temps[i].path, temp.c_str(), temp.size() + 1);
    g_temps[i].state.store(2);
    return i;
  }
  return kSlots;
}

void unregister_temp(std::size_t slot) {
  if (slot < kSlots) g_temps[slot].state.store(0);
}

extern "C" void remove_temps_and_reraise(int sig) {
  for (auto& t : g_temps)
    if (t.state.load() == 2) ::unlink(t.path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

}  // namespace

void remove_temporaries_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_temps_and_reraise;
  sigemptyset(&action.sa_mask);
  for (int sig : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    // A signal the parent told us to ignore (a background job's SIGINT, nohup) stays ignored.
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(sig, &action, nullptr);
  }
}

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  static std::atomic<unsigned> counter{0};
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (std::error_code ec; !fs::is_directory(dir, ec))
    throw InputError(SourceLocation{path, 0, 0}, "cannot write: folder '" + dir.string() +
                                                     "' does not exist");
  const std::string temp = (dir / ("." + target.filename().string() + ".tmp" +
                                   std::to_string(::getpid()) + "_" + std::to_string(counter++)))
                               .string();
  const std::size_t slot = register_temp(temp);
  try {
    write(temp);
    std::error_code ec;
    fs::rename(temp, target, ec);
    if (ec) throw InputError(SourceLocation{path, 0, 0}, "cannot write: " + ec.message());
    unregister_temp(slot);
  } catch (...) {
    std::error_code ignore;
    fs::remove(temp, ignore);
    unregister_temp(slot);
    throw;
  }
}

void write_file_atomically(const std::string& path, const std::string& content) {
  write_atomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw InputError(SourceLocation{path, 0, 0}, "cannot write: permission denied or bad path");
    out.write(content.data(), std::streamsize(content.size()));
    out.close();
    if (!out) throw InputError(SourceLocation{path, 0, 0}, "cannot write: disk full or I/O error");
  });
}

}  // namespace ms
