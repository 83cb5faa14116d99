// The process's lease keeper: the sessions a process has open in one store share one keeper, which
// renews every one of their leases each kHeartbeatMs (an idle participant keeps the session) and
// lets a closed session's lease go.
#include <gtest/gtest.h>

#include <sqlite3.h>

#include <chrono>
#include <map>
#include <thread>

#include "core_fixtures.hpp"
#include "studyapp/core/lease_keeper.hpp"
#include "studyapp/core/session_lease.hpp"
#include "studyapp/core/sqlite_handle.hpp"

namespace ms {
namespace {

std::map<std::int64_t, std::int64_t> heartbeats(const std::string& db) {
  sqlite::Database raw(db, SQLITE_OPEN_READONLY);
  sqlite::Statement q(raw, "SELECT session, heartbeat_ms FROM leases");
  std::map<std::int64_t, std::int64_t> out;
  while (q.step()) out[q.column_int64(0)] = q.column_int64(1);
  return out;
}

TEST(LeaseKeeper, OneKeeperPerStoreRenewsEveryOpenSessionsLease) {
  test::TempDir dir;
  testing::SmallStudy study(dir);
  const std::string db = dir.file("r.sqlite");
  EXPECT_EQ(LeaseKeeper::of(db), LeaseKeeper::of(db));
  EXPECT_NE(LeaseKeeper::of(db), LeaseKeeper::of(dir.file("other.sqlite")));
  const std::int64_t opened_ms = unix_now_ms();
  Session a = study.open("P1", db, opened_ms);
  Session b = study.open("P2", db, opened_ms);
  {
    Session c = study.open("P3", db, opened_ms);
    EXPECT_EQ(heartbeats(db).size(), 3u);
  }
  const auto before = heartbeats(db);
  ASSERT_EQ(before.size(), 2u);  // the closed session's lease is gone
  std::this_thread::sleep_for(std::chrono::milliseconds(kHeartbeatMs + 1500));
  const auto after = heartbeats(db);
  ASSERT_EQ(after.size(), 2u);
  for (const Session* s : {&a, &b}) {
    ASSERT_TRUE(after.count(s->id()));
    EXPECT_GE(after.at(s->id()), before.at(s->id()) + kHeartbeatMs / 2) << "session " << s->id() << " not renewed";
  }
}

}  // namespace
}  // namespace ms
