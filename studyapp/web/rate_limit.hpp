// Request rate limits per key (a participant link's token; one shared key for requests without a known
// link): a token bucket of `burst` requests refilled at `per_second`. A page's own pace (a few requests
// per trial) never meets it; a script hammering one link or guessing links does.
#pragma once
#include <chrono>
#include <map>
#include <mutex>
#include <string>

namespace ms::web {

class RateLimit {
 public:
  using Clock = std::chrono::steady_clock;
  RateLimit(double burst, double per_second) : burst_(burst), per_second_(per_second) {}

  // True when a request under `key` may go ahead now (and takes one from its bucket).
  bool allow(const std::string& key, Clock::time_point now = Clock::now());

 private:
  struct Bucket {
    double tokens;
    Clock::time_point last;
  };
  double burst_, per_second_;
  std::mutex mutex_;
  std::map<std::string, Bucket> buckets_;
};

}  // namespace ms::web
