// LeaseKeeper: one registry entry per store location; see lease_keeper.hpp.
#include "studyapp/core/lease_keeper.hpp"

#include <chrono>
#include <map>
#include <vector>

#include "studyapp/core/results_store.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/core/session_lease.hpp"

namespace ms {

std::shared_ptr<LeaseKeeper> LeaseKeeper::of(const std::string& db_path) {
  static std::mutex registry_mutex;
  static std::map<std::string, std::weak_ptr<LeaseKeeper>> registry;
  const std::lock_guard lock(registry_mutex);
  std::weak_ptr<LeaseKeeper>& entry = registry[db_path];
  if (auto keeper = entry.lock()) return keeper;
  std::shared_ptr<LeaseKeeper> keeper(new LeaseKeeper(db_path));
  entry = keeper;
  return keeper;
}

LeaseKeeper::LeaseKeeper(std::string db_path) : db_path_(std::move(db_path)), thread_([this] { run(); }) {}

LeaseKeeper::~LeaseKeeper() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void LeaseKeeper::keep(std::int64_t session) {
  const std::lock_guard lock(mutex_);
  sessions_.insert(session);
}

void LeaseKeeper::drop(std::int64_t session) {
  const std::lock_guard lock(mutex_);
  sessions_.erase(session);
}

void LeaseKeeper::run() {
  std::unique_ptr<ResultsStore> store;
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, std::chrono::milliseconds(kHeartbeatMs), [this] { return stop_; })) {
    const std::vector<std::int64_t> due(sessions_.begin(), sessions_.end());
    lock.unlock();  // sessions open and close while the beat is written
    try {
      if (!store && !due.empty()) store = std::make_unique<ResultsStore>(db_path_, ResultsStore::Mode::open_existing);
      for (const std::int64_t session : due) {
        try {
          store->renew_lease(session, this_process(), unix_now_ms());
        } catch (const SessionInUse&) {
          // A lease taken over is found by the next write of that session itself, which refuses it.
        }
      }
    } catch (const std::exception&) {
      store.reset();  // a lost connection (a restarted server) is opened anew at the next beat
    }
    lock.lock();
  }
}

}  // namespace ms
