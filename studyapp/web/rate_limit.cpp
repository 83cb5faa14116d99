// RateLimit: refill by the time since the bucket's last request, capped at the burst.
#include "studyapp/web/rate_limit.hpp"

#include <algorithm>

namespace ms::web {

bool RateLimit::allow(const std::string& key, Clock::time_point now) {
  const std::lock_guard<std::mutex> lock(mutex_);
  auto [it, added] = buckets_.try_emplace(key, Bucket{burst_, now});
  Bucket& b = it->second;
  if (!added) {
    const double elapsed_s = std::chrono::duration<double>(now - b.last).count();
    b.tokens = std::min(burst_, b.tokens + elapsed_s * per_second_);
    b.last = now;
  }
  if (b.tokens < 1.0) return false;
  b.tokens -= 1.0;
  return true;
}

}  // namespace ms::web
