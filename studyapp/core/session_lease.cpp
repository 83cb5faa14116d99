// Session leases: who holds a session and when a lease is stale; see session_lease.hpp.
#include "studyapp/core/session_lease.hpp"

#include <unistd.h>

#include <array>
#include <fstream>
#include <sstream>

namespace ms {

std::string process_start_time(std::int64_t pid) {
  if (pid <= 0) return {};
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!in || !std::getline(in, stat)) return {};
  // Field 2 is the command in parentheses and may hold spaces: count fields after its last ')'.
  const auto close = stat.rfind(')');
  if (close == std::string::npos) return {};
  std::istringstream rest(stat.substr(close + 1));
  std::string field;
  for (int i = 3; i <= 22 && rest >> field; ++i) {
    if (i == 3 && (field == "Z" || field == "X")) return {};  // killed, not yet reaped: gone all the same
    if (i == 22) return field;
  }
  return {};
}

LeaseHolder this_process() {
  std::array<char, 256> name{};
  if (gethostname(name.data(), name.size() - 1) != 0) name[0] = '\0';
  const std::int64_t pid = getpid();
  return {name.data(), pid, process_start_time(pid)};
}

bool lease_is_stale(const LeaseHolder& holder, std::int64_t heartbeat_ms, std::int64_t now_ms) {
  if (holder.host == this_process().host) {
    const std::string start = process_start_time(holder.pid);
    return start.empty() || start != holder.process_start;
  }
  return now_ms - heartbeat_ms > kLeaseTimeoutMs;
}

std::string describe(const LeaseHolder& holder) {
  return "pid " + std::to_string(holder.pid) + " on " + (holder.host.empty() ? "an unnamed host" : holder.host);
}

}  // namespace ms
