// Which back end a location names; see store_location.hpp.
#include "studyapp/core/store_location.hpp"

#include <filesystem>

#include "studyapp/core/postgres_store.hpp"

namespace ms {

bool is_postgres_uri(std::string_view location) {
  return location.rfind("postgresql://", 0) == 0 || location.rfind("postgres://", 0) == 0;
}

bool store_exists(const std::string& location) {
  if (is_postgres_uri(location)) return postgres_store_exists(location);
  std::error_code ec;
  return std::filesystem::exists(location, ec) && std::filesystem::file_size(location, ec) > 0;
}

}  // namespace ms
