// ResultsStore: schema, one-transaction-per-response, resume, refusal of foreign files, and crash
// safety (a child process killed with SIGKILL mid-session loses no committed response). The tests of
// behaviour run on both back ends (StoreOnBoth); those of the SQLite file itself on SQLite only.
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

#include "studyapp/core/results_store.hpp"
#include "studyapp/core/sqlite_handle.hpp"
#include "support/test_stores.hpp"
#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"

namespace ms {
namespace {

std::vector<TrialRecord> identify_block(int n) {
  std::vector<TrialRecord> trials;
  for (int i = 0; i < n; ++i)
    trials.push_back({0, "id1", "identify", i, {"s" + std::to_string(i % 3)}, {"hash" + std::to_string(i % 3)}});
  return trials;
}

ResponseRecord answer(int trial, const std::string& value_json) {
  return {{0, trial}, value_json, 100.0 + trial, 1 + trial % 2, 1'700'000'000'000 + trial};
}

// A store holding one study, one participant and one session of n identify trials.
std::int64_t make_session(ResultsStore& store, int n) {
  store.add_study({"demo", "Demo study", std::string(64, 'a'), "study: demo\n", false});
  const std::int64_t p = store.add_participant("demo", "P01", 1'700'000'000'000);
  const std::int64_t s = store.start_session(p, 1'700'000'000'000, 42u);
  store.record_trials(s, identify_block(n));
  return s;
}

class StoreOnBoth : public ::testing::TestWithParam<test::Backend> {};
INSTANTIATE_TEST_SUITE_P(Backends, StoreOnBoth, ::testing::Values(test::Backend::sqlite, test::Backend::postgresql),
                         test::backend_name);

TEST_P(StoreOnBoth, RecordsAndReadsBackResponses) {
  test::TestStore where(GetParam());
  SKIP_WITHOUT_STORE(where);
  ResultsStore store(where.location());
  const auto s = make_session(store, 4);
  EXPECT_EQ(store.first_unanswered_trial(s), (TrialPosition{0, 0}));
  store.record_response(s, answer(0, "\"metal\""));
  store.record_response(s, answer(1, "{\"a\":1}"));
  EXPECT_EQ(store.first_unanswered_trial(s), (TrialPosition{0, 2}));
  const auto r = store.response(s, {0, 1});
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->value_json, "{\"a\":1}");
  EXPECT_DOUBLE_EQ(r->rt_ms, 101.0);
  EXPECT_EQ(r->plays, 2);
  EXPECT_EQ(r->timestamp_ms, 1'700'000'000'001);
  EXPECT_FALSE(store.response(s, {0, 2}).has_value());
  store.record_response(s, answer(2, "3"));
  store.record_response(s, answer(3, "4"));
  EXPECT_FALSE(store.first_unanswered_trial(s).has_value());
  EXPECT_EQ(store.count("responses"), 4);
  EXPECT_EQ(store.integrity_check(), "ok");
}

TEST(ResultsStore, UsesWalFullSyncForeignKeysAndSchemaVersion) {
  test::TempDir dir;
  const std::string path = dir.file("r.sqlite");
  { ResultsStore store(path); }
  sqlite::Database db(path, 0x2 /* SQLITE_OPEN_READWRITE */);
  auto one = [&](const char* sql) {
    sqlite::Statement q(db, sql);
    EXPECT_TRUE(q.step()) << sql;
    return q.column_text(0);
  };
  EXPECT_EQ(one("PRAGMA journal_mode"), "wal");  // persistent in the file
  EXPECT_EQ(one("SELECT version FROM schema_version"), std::to_string(ResultsStore::kSchemaVersion));
  EXPECT_EQ(one("PRAGMA application_id"), std::to_string(ResultsStore::kApplicationId));
  ResultsStore again(path);  // reopening an own file works
  EXPECT_EQ(again.integrity_check(), "ok");
}

TEST_P(StoreOnBoth, ReRecordingATrialIsAnErrorAndKeepsTheFirstAnswer) {
  test::TestStore where(GetParam());
  SKIP_WITHOUT_STORE(where);
  ResultsStore store(where.location());
  const auto s = make_session(store, 2);
  store.record_response(s, answer(0, "\"glass\""));
  try {
    store.record_response(s, answer(0, "\"wood\""));
    FAIL() << "a second answer to one trial was stored";
  } catch (const StoreError& e) {
    EXPECT_TRUE(e.refused()) << e.what();
    EXPECT_NE(std::string(e.what()).find("already answered"), std::string::npos) << e.what();
  }
  EXPECT_EQ(store.response(s, {0, 0})->value_json, "\"glass\"");
  // The prepared statement stays usable after the failure.
  store.record_response(s, answer(1, "\"wood\""));
  EXPECT_EQ(store.count("responses"), 2);
}

TEST_P(StoreOnBoth, RefusesUnscheduledTrialsAndInvalidJson) {
  test::TestStore where(GetParam());
  SKIP_WITHOUT_STORE(where);
  ResultsStore store(where.location());
  const auto s = make_session(store, 2);
  EXPECT_THROW(store.record_response(s, answer(7, "1")), StoreError);      // foreign key
  EXPECT_THROW(store.record_response(s, answer(0, "metal")), StoreError);  // not JSON
  EXPECT_THROW(store.record_event(s, {{0, 9}, EventKind::play, "s0", 1}), StoreError);
  EXPECT_THROW(store.record_event(s, {{0, 0}, EventKind::play, "s0", 1, "{oops"}), StoreError);
  store.record_event(s, {{0, 0}, EventKind::switch_to, "s0", 1});
  EXPECT_EQ(store.count("responses"), 0);
  EXPECT_EQ(store.count("events"), 1);
}

TEST_P(StoreOnBoth, StudyWithSameIdMustHaveSameProtocol) {
  test::TestStore where(GetParam());
  SKIP_WITHOUT_STORE(where);
  ResultsStore store(where.location());
  make_session(store, 1);
  EXPECT_NO_THROW(store.add_study({"demo", "Demo study", std::string(64, 'a'), "study: demo\n", false}));
  EXPECT_THROW(store.add_study({"demo", "Demo", std::string(64, 'b'), "x", false}), InputError);
  ASSERT_EQ(store.studies().size(), 1u);
  EXPECT_EQ(store.studies()[0].title, "Demo study");
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(ResultsStore, ForeignFilesAreRefusedByNameAndLeftUntouched) {
  test::TempDir dir;
  const std::string csv = dir.write("data.sqlite", "stimuli,response\na,b\n");
  try {
    ResultsStore store(csv);
    FAIL() << "opened a CSV file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(csv), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a ModalStudy results database"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(csv), "stimuli,response\na,b\n");
  // An empty file is what an interrupted creation leaves: only a run that may create takes it as new.
  const std::string empty = dir.write("empty.sqlite", "");
  EXPECT_THROW(ResultsStore(empty, ResultsStore::Mode::open_existing), InputError);
  EXPECT_EQ(std::filesystem::file_size(empty), 0u);
  EXPECT_EQ(ResultsStore{empty}.integrity_check(), "ok");

  // Another application's SQLite database.
  const std::string other = dir.file("other.sqlite");
  {
    sqlite::Database db(other, 0x2 | 0x4 /* READWRITE | CREATE */);
    db.exec("CREATE TABLE t(x); INSERT INTO t VALUES (1)");
  }
  const std::string before = slurp(other);
  EXPECT_THROW(ResultsStore{other}, InputError);
  EXPECT_EQ(slurp(other), before);
  EXPECT_FALSE(std::filesystem::exists(other + "-wal"));

  EXPECT_THROW(ResultsStore(dir.file("missing.sqlite"), ResultsStore::Mode::open_existing), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("missing.sqlite")));
  EXPECT_THROW(ResultsStore(dir.file("no/such/folder/r.sqlite")), InputError);
}

TEST(ResultsStore, NewerSchemaVersionIsRefused) {
  test::TempDir dir;
  const std::string path = dir.file("r.sqlite");
  {
    ResultsStore store(path);
    make_session(store, 1);
  }
  {
    sqlite::Database db(path, 0x2);
    db.exec("PRAGMA journal_mode=DELETE; UPDATE schema_version SET version = 99");
  }
  const std::string before = slurp(path);
  try {
    ResultsStore store(path);
    FAIL() << "opened a newer schema";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("schema version 99"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(path), before);
}

// The child records responses in a loop and reports each COMMIT through a pipe; the parent kills
// it with SIGKILL after K reports. Every reported response must survive, and the file stay sound.
TEST_P(StoreOnBoth, CommittedResponsesSurviveSigkill) {
  test::TestStore where(GetParam());
  SKIP_WITHOUT_STORE(where);
  const std::string path = where.location();
  constexpr int kTrials = 2000, kCommitted = 40;
  std::int64_t session = 0;
  {
    ResultsStore store(path);
    session = make_session(store, kTrials);
  }  // closed before fork: a database connection must not cross fork()
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(fds[0]);
    try {
      ResultsStore store(path);
      for (int i = 0; i < kTrials; ++i) {
        store.record_response(session, answer(i, std::to_string(i)));
        const char c = 'k';
        if (::write(fds[1], &c, 1) != 1) ::_exit(3);
      }
    } catch (...) {
      ::_exit(2);
    }
    ::_exit(0);
  }
  ::close(fds[1]);
  int reported = 0;
  char c = 0;
  while (reported < kCommitted && ::read(fds[0], &c, 1) == 1) ++reported;
  ASSERT_EQ(::kill(child, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ::close(fds[0]);
  ASSERT_EQ(reported, kCommitted);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "child ended before the kill";

  ResultsStore store(path);
  EXPECT_EQ(store.integrity_check(), "ok");
  for (int i = 0; i < kCommitted; ++i) {
    const auto r = store.response(session, {0, i});
    ASSERT_TRUE(r.has_value()) << "lost committed response " << i;
    EXPECT_EQ(r->value_json, std::to_string(i));
    EXPECT_DOUBLE_EQ(r->rt_ms, 100.0 + i);
  }
  const auto next = store.first_unanswered_trial(session);
  ASSERT_TRUE(next.has_value());
  EXPECT_GE(next->trial_index, kCommitted);
  EXPECT_EQ(store.count("responses"), next->trial_index);  // no gaps: answered exactly 0..next-1
  store.record_response(session, answer(next->trial_index, "\"resumed\""));  // and the session resumes
}

}  // namespace
}  // namespace ms
