// Which back end a location names; see store_location.hpp.
#include "studyapp/core/store_location.hpp"

#include <algorithm>
#include <filesystem>

#include "studyapp/core/postgres_store.hpp"

namespace ms {

bool is_postgres_uri(std::string_view location) {
  return location.rfind("postgresql://", 0) == 0 || location.rfind("postgres://", 0) == 0;
}

std::string location_without_password(const std::string& uri) {
  const auto scheme = uri.find("://");
  if (scheme == std::string::npos) return uri;
  const auto start = scheme + 3;
  const auto end = std::min(uri.find('/', start), uri.size());
  const auto at = uri.rfind('@', end == 0 ? 0 : end - 1);
  if (at == std::string::npos || at < start) return uri;
  const auto colon = uri.find(':', start);
  if (colon == std::string::npos || colon > at) return uri;
  return uri.substr(0, colon) + uri.substr(at);
}

bool store_exists(const std::string& location) {
  if (is_postgres_uri(location)) return postgres_store_exists(location);
  std::error_code ec;
  return std::filesystem::exists(location, ec) && std::filesystem::file_size(location, ec) > 0;
}

}  // namespace ms
