// The results store's back ends for tests run on both: a file in a fresh folder (SQLite), or a schema of
// its own in the PostgreSQL database named by MODALSTUDY_TEST_POSTGRES_URL (scripts/test.sh starts one),
// dropped afterwards. Without that variable the PostgreSQL cases skip, saying why.
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <string>

#include "studyapp/core/postgres_handle.hpp"
#include "support/test_util.hpp"

namespace ms::test {

enum class Backend { sqlite, postgresql };

inline std::string backend_name(const ::testing::TestParamInfo<Backend>& info) {
  return info.param == Backend::sqlite ? "SQLite" : "PostgreSQL";
}

inline const char* postgres_test_url() {
  const char* url = std::getenv("MODALSTUDY_TEST_POSTGRES_URL");
  return url && *url ? url : nullptr;
}

inline constexpr const char* kNoPostgres =
    "MODALSTUDY_TEST_POSTGRES_URL is not set (scripts/test.sh starts a PostgreSQL server and sets it)";

// One empty store location. PostgreSQL: a fresh schema first in the search path, and the connections'
// application_name set to it, so a test can find (and terminate) its own server connections.
class TestStore {
 public:
  explicit TestStore(Backend backend, const std::string& file = "r.sqlite") : backend_(backend) {
    if (backend_ == Backend::sqlite) {
      location_ = dir_.file(file);
      return;
    }
    const char* url = postgres_test_url();
    if (!url) return;
    std::random_device rd;
    schema_ = "t_" + std::to_string(rd()) + "_" + std::to_string(rd());
    admin().exec("CREATE SCHEMA " + schema_);
    const std::string base(url);
    location_ = base + (base.find('?') == std::string::npos ? "?" : "&") + "options=-csearch_path%3D" + schema_ +
                "&application_name=" + schema_;
  }
  ~TestStore() {
    if (schema_.empty()) return;
    try {
      admin().exec("DROP SCHEMA " + schema_ + " CASCADE");
    } catch (...) {
    }
  }
  TestStore(const TestStore&) = delete;
  TestStore& operator=(const TestStore&) = delete;

  bool available() const { return !location_.empty(); }
  const std::string& location() const { return location_; }
  const std::string& schema() const { return schema_; }
  const TempDir& dir() const { return dir_; }
  Backend backend() const { return backend_; }
  // A connection of its own to the test's PostgreSQL schema (for tampering and for blocking).
  pg::Connection raw() const { return pg::Connection(location_); }
  pg::Connection admin() const { return pg::Connection(postgres_test_url()); }

 private:
  Backend backend_;
  TempDir dir_;
  std::string location_, schema_;
};

}  // namespace ms::test

// In a test on both back ends: skip the PostgreSQL case when no server was given.
#define SKIP_WITHOUT_STORE(store) \
  if (!(store).available()) GTEST_SKIP() << ms::test::kNoPostgres
