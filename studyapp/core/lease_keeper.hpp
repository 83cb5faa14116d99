// The heartbeat of every session a process has open in one store: each open session's lease renewed
// every kHeartbeatMs on one connection of the keeper's own, so an idle participant (reading
// instructions, on a break) keeps the session. A server with hundreds of participants holds one extra
// connection and one thread per store, not one of each per participant.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>

namespace ms {

class LeaseKeeper {
 public:
  // The keeper of the store at `db_path`, shared by the sessions that hold it; it stops when the last
  // one lets go.
  static std::shared_ptr<LeaseKeeper> of(const std::string& db_path);

  void keep(std::int64_t session);
  void drop(std::int64_t session);

  ~LeaseKeeper();
  LeaseKeeper(const LeaseKeeper&) = delete;
  LeaseKeeper& operator=(const LeaseKeeper&) = delete;

 private:
  explicit LeaseKeeper(std::string db_path);
  void run();

  const std::string db_path_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::set<std::int64_t> sessions_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace ms
