// Session leases: which process is running a session, so two booths (or two windows) can never answer
// for one participant at once. A lease names its holder (host, pid, the process's start time, so a
// reused pid is not mistaken for the holder) and carries a heartbeat renewed while the session is open.
// A lease is stale when its holder is known to be gone: on this host, the process no longer exists;
// elsewhere, the heartbeat is older than kLeaseTimeoutMs. A stale lease never blocks a resume.
#pragma once
#include <cstdint>
#include <string>

namespace ms {

struct LeaseHolder {
  std::string host;
  std::int64_t pid = 0;
  std::string process_start;  // the kernel's start time of the process (/proc/PID/stat field 22)
  friend bool operator==(const LeaseHolder&, const LeaseHolder&) = default;
};

// Heartbeats every kHeartbeatMs; another host's lease older than kLeaseTimeoutMs is taken over.
inline constexpr std::int64_t kHeartbeatMs = 10'000;
inline constexpr std::int64_t kLeaseTimeoutMs = 60'000;

LeaseHolder this_process();

// The start time of a running process; "" when no process has that pid, it is a zombie (killed but
// not yet reaped by its parent), or /proc cannot be read.
std::string process_start_time(std::int64_t pid);

bool lease_is_stale(const LeaseHolder& holder, std::int64_t heartbeat_ms, std::int64_t now_ms);

// "pid 4242 on booth-2" for messages.
std::string describe(const LeaseHolder& holder);

}  // namespace ms
