// The PostgreSQL back end where it differs from a file: bad locations refused in one line without the
// password, booths in separate processes racing for one participant, many writers into one study, and a
// connection killed in the middle of an answer. Needs MODALSTUDY_TEST_POSTGRES_URL (else skipped).
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <mutex>
#include <set>
#include <thread>

#include "core_fixtures.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/postgres_handle.hpp"
#include "studyapp/core/results_store.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/core/store_location.hpp"
#include "support/test_stores.hpp"
#include "synthesis/input_error.hpp"

namespace ms {
namespace {

const StudyRecord kStudy{"demo", "Demo study", std::string(64, 'a'), "study: demo\n", false};

std::vector<TrialRecord> trials(int n) {
  std::vector<TrialRecord> out;
  for (int i = 0; i < n; ++i) out.push_back({0, "id1", "identify", i, {"s"}, {"h"}});
  return out;
}

SessionRequest request(const std::string& participant, int n, LeaseHolder holder) {
  SessionRequest r{"demo", participant, unix_now_ms(), 42u, trials(n)};
  r.holder = std::move(holder);
  return r;
}

std::string refusal(const std::string& location, StoreMode mode = StoreMode::create_or_open) {
  try {
    ResultsStore store(location, mode);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

#define REQUIRE_POSTGRES(store)              \
  test::TestStore store(test::Backend::postgresql); \
  SKIP_WITHOUT_STORE(store)

TEST(PostgresStore, ALocationIsChosenByItsScheme) {
  EXPECT_TRUE(is_postgres_uri("postgresql://u@h:5432/db"));
  EXPECT_TRUE(is_postgres_uri("postgres://h/db"));
  EXPECT_FALSE(is_postgres_uri("results/postgresql.sqlite"));
  EXPECT_FALSE(is_postgres_uri("./postgresql://x"));
}

TEST(PostgresStore, AMalformedUriOrAnUnreachableServerIsOneLineWithoutThePassword) {
  const std::string bad = refusal("postgresql://ana:s3cret@127.0.0.1:notaport/study");
  EXPECT_NE(bad.find("postgresql://ana@127.0.0.1:notaport/study"), std::string::npos) << bad;
  EXPECT_EQ(bad.find("s3cret"), std::string::npos) << bad;
  EXPECT_EQ(bad.find('\n'), std::string::npos) << bad;

  // Port 1 on loopback: nothing listens there, the refusal is immediate.
  const std::string down = refusal("postgresql://ana:s3cret@127.0.0.1:1/study");
  EXPECT_NE(down.find("postgresql://ana@127.0.0.1:1/study: cannot connect to the PostgreSQL server"),
            std::string::npos) << down;
  EXPECT_EQ(down.find("s3cret"), std::string::npos) << down;
  EXPECT_EQ(down.find('\n'), std::string::npos) << down;
}

TEST(PostgresStore, AnotherApplicationsDatabaseIsRefusedAndLeftAlone) {
  REQUIRE_POSTGRES(where);
  where.raw().exec("CREATE TABLE orders(id INTEGER); INSERT INTO orders VALUES (7)");
  const std::string why = refusal(where.location());
  EXPECT_NE(why.find("not a ModalStudy results database (the database holds 1 tables of another application)"),
            std::string::npos) << why;
  const pg::Result tables = where.raw().exec("SELECT count(*) FROM pg_tables WHERE schemaname = current_schema()");
  EXPECT_EQ(tables.text(0, 0), "1");  // nothing created beside it

  // A table named like ours but not made by us.
  REQUIRE_POSTGRES(other);
  other.raw().exec("CREATE TABLE schema_version(version INTEGER)");
  EXPECT_NE(refusal(other.location()).find("another application's schema_version table"), std::string::npos);
}

TEST(PostgresStore, AnEmptyDatabaseIsCreatedOnlyWhenAsked) {
  REQUIRE_POSTGRES(where);
  EXPECT_FALSE(store_exists(where.location()));
  EXPECT_NE(refusal(where.location(), StoreMode::read_only).find("holds no ModalStudy results store"),
            std::string::npos);
  EXPECT_NE(refusal(where.location(), StoreMode::open_existing).find("holds no ModalStudy results store"),
            std::string::npos);
  EXPECT_FALSE(store_exists(where.location()));
  ResultsStore store(where.location());
  EXPECT_EQ(store.schema_version(), ResultsStore::kSchemaVersion);
  EXPECT_TRUE(store_exists(where.location()));
  const pg::Result v = where.raw().exec("SELECT version FROM schema_version");
  ASSERT_EQ(v.rows(), 1);
  EXPECT_EQ(v.text(0, 0), std::to_string(ResultsStore::kSchemaVersion));
}

TEST(PostgresStore, ANewerSchemaIsRefusedAndNotWritten) {
  REQUIRE_POSTGRES(where);
  { ResultsStore store(where.location()); }
  where.raw().exec("UPDATE schema_version SET version = 99");
  const std::string why = refusal(where.location());
  EXPECT_NE(why.find("schema version 99 is newer than this program supports"), std::string::npos) << why;
  EXPECT_EQ(where.raw().exec("SELECT count(*), max(version) FROM schema_version").text(0, 0), "1");
}

TEST(PostgresStore, AReadOnlyStoreRefusesWrites) {
  REQUIRE_POSTGRES(where);
  std::int64_t session = 0;
  {
    ResultsStore store(where.location());
    session = store.open_session(kStudy, request("P1", 2, this_process())).session;
  }
  ResultsStore reader(where.location(), StoreMode::read_only);
  EXPECT_THROW(reader.record_response(session, {{0, 0}, "1", 1.0, 1, 1}), StoreError);
  EXPECT_THROW(reader.add_participant("demo", "P2", 1), StoreError);
  EXPECT_EQ(reader.count("responses"), 0);
  EXPECT_EQ(reader.count("participants"), 1);
}

// Four booths (processes) open the same participant at the same moment: the database lets exactly one run it.
TEST(PostgresStore, OfBoothsRacingForOneParticipantExactlyOneWins) {
  REQUIRE_POSTGRES(where);
  { ResultsStore store(where.location()); }
  constexpr int kBooths = 4;
  int go[2], done[2], release[2];  // go: one byte each; done: each reports; release: closed at the end
  ASSERT_EQ(::pipe(go), 0);
  ASSERT_EQ(::pipe(done), 0);
  ASSERT_EQ(::pipe(release), 0);
  std::vector<pid_t> booths;
  for (int b = 0; b < kBooths; ++b) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::close(go[1]);
      ::close(release[1]);
      int code = 6;  // 0: ran the participant, 1: refused as in use, else failed
      try {
        ResultsStore store(where.location());
        char c = 0;
        if (::read(go[0], &c, 1) != 1) ::_exit(5);
        try {
          store.open_session(kStudy, request("P07", 3, this_process()));
          code = 0;
        } catch (const SessionInUse&) {
          code = 1;
        }
        (void)!::write(done[1], "d", 1);
        (void)!::read(release[0], &c, 1);  // stay alive (lease held) until the parent closes the pipe
      } catch (...) {
        (void)!::write(done[1], "d", 1);
      }
      ::_exit(code);
    }
    booths.push_back(child);
  }
  ::close(go[0]);
  ASSERT_EQ(::write(go[1], "gggg", kBooths), kBooths);
  char c = 0;
  for (int b = 0; b < kBooths; ++b) ASSERT_EQ(::read(done[0], &c, 1), 1);
  ::close(go[1]);
  ::close(release[1]);
  int winners = 0, refused = 0;
  for (pid_t child : booths) {
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    winners += WEXITSTATUS(status) == 0;
    refused += WEXITSTATUS(status) == 1;
  }
  EXPECT_EQ(winners, 1);
  EXPECT_EQ(refused, kBooths - 1);
  ResultsStore store(where.location(), StoreMode::read_only);
  EXPECT_EQ(store.count("participants"), 1);
  EXPECT_EQ(store.count("sessions"), 1);
  EXPECT_EQ(store.count("trials"), 3);
  EXPECT_EQ(store.count("leases"), 1);
}

// Two connections in one process with different holders (a live local process and another booth whose
// heartbeat is fresh) open one participant from two threads: one wins, the other is told who runs it.
TEST(PostgresStore, TwoConnectionsWithDifferentHoldersNeverBothRunAParticipant) {
  REQUIRE_POSTGRES(where);
  for (int round = 0; round < 10; ++round) {
    ResultsStore a(where.location()), b(where.location());
    const std::string participant = "R" + std::to_string(round);
    int wins = 0;
    std::string refusal_text;
    std::mutex m;
    auto run = [&](ResultsStore& store, LeaseHolder holder) {
      try {
        store.open_session(kStudy, request(participant, 2, std::move(holder)));
        std::lock_guard lock(m);
        ++wins;
      } catch (const SessionInUse& e) {
        std::lock_guard lock(m);
        refusal_text = e.what();
      }
    };
    std::thread ta(run, std::ref(a), this_process());
    std::thread tb(run, std::ref(b), LeaseHolder{"booth-2", 4242, "77"});
    ta.join();
    tb.join();
    EXPECT_EQ(wins, 1) << "round " << round;
    EXPECT_NE(refusal_text.find("is being run right now by pid"), std::string::npos) << refusal_text;
  }
}

// Eight processes answer for eight participants of one study at once, each also trying to answer one
// trial twice: every answer is stored exactly once.
TEST(PostgresStore, ConcurrentWritersToOneStudyLoseAndDuplicateNothing) {
  REQUIRE_POSTGRES(where);
  { ResultsStore store(where.location()); }
  constexpr int kWriters = 8, kTrials = 40;
  std::vector<pid_t> writers;
  for (int w = 0; w < kWriters; ++w) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      try {
        ResultsStore store(where.location());
        const auto s = store.open_session(kStudy, request("W" + std::to_string(w), kTrials, this_process())).session;
        int refused = 0;
        for (int i = 0; i < kTrials; ++i) {
          store.record_response(s, {{0, i}, std::to_string(w * 1000 + i), 0.1 * i, 1, 1000 + i});
          store.record_event(s, {{0, i}, EventKind::play, "s", 1000 + i});
          try {
            store.record_response(s, {{0, i}, "-1", 0.0, 1, 1000 + i});
          } catch (const StoreError& e) {
            refused += e.refused();
          }
        }
        ::_exit(refused == kTrials ? 0 : 3);
      } catch (...) {
        ::_exit(4);
      }
    }
    writers.push_back(child);
  }
  for (pid_t child : writers) {
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "writer exit " << status;
  }
  ResultsStore store(where.location(), StoreMode::read_only);
  const auto rows = store.response_rows();
  ASSERT_EQ(rows.size(), std::size_t(kWriters * kTrials));
  std::set<std::string> values;
  for (const ResponseRow& r : rows) {
    values.insert(r.value_json);
    const int w = std::stoi(r.participant_code.substr(1));
    EXPECT_EQ(r.value_json, std::to_string(w * 1000 + r.trial_index));
    EXPECT_DOUBLE_EQ(r.rt_ms, 0.1 * r.trial_index);  // reals come back exactly
  }
  EXPECT_EQ(values.size(), rows.size());
  EXPECT_EQ(store.count("events"), kWriters * kTrials);
  EXPECT_EQ(store.count("sessions"), kWriters);
}

// An answer whose INSERT waits on another transaction is cut off by pg_terminate_backend: nothing of it
// stays, the store refuses nothing afterwards and the same answer can be given again.
TEST(PostgresStore, AConnectionKilledMidAnswerLeavesTheStoreUnchanged) {
  REQUIRE_POSTGRES(where);
  ResultsStore store(where.location());
  const auto s = store.open_session(kStudy, request("K1", 2, this_process())).session;
  pg::Connection blocker = where.raw();
  blocker.exec("BEGIN");
  blocker.exec("INSERT INTO responses(session, block_index, trial_index, value, rt_ms, plays, timestamp) "
               "VALUES ($1, 0, 0, '\"blocker\"', 1, 1, 1)",
               {std::to_string(s).c_str()});
  std::string error;
  std::thread answer([&] {
    try {
      store.record_response(s, {{0, 0}, "\"answer\"", 12.5, 1, unix_now_ms()});
    } catch (const StoreError& e) {
      error = e.what();
    }
  });
  // Wait until the answer's INSERT is blocked inside its transaction, then kill its connection.
  pg::Connection killer = where.admin();
  bool killed = false;
  for (int i = 0; i < 500 && !killed; ++i) {
    const pg::Result r = killer.exec(
        "SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE application_name = $1 "
        "AND wait_event_type = 'Lock' AND query LIKE 'INSERT INTO responses%'",
        {where.schema().c_str()});
    killed = r.rows() == 1 && r.text(0, 0) == "t";
    if (!killed) ::usleep(10'000);
  }
  answer.join();
  blocker.exec("ROLLBACK");
  ASSERT_TRUE(killed) << "the answer never waited on the blocker";
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(error.rfind("postgresql://", 0), 0u) << error;  // names the store
  ResultsStore after(where.location());
  EXPECT_EQ(after.count("responses"), 0);
  EXPECT_EQ(after.first_unanswered_trial(s), (TrialPosition{0, 0}));
  after.record_response(s, {{0, 0}, "\"again\"", 12.5, 1, unix_now_ms()});
  EXPECT_EQ(after.response(s, {0, 0})->value_json, "\"again\"");
}

// One session, answered the same way (same times, same reaction times) into a file and into PostgreSQL:
// the exports are the same bytes, but for study.json's "source" (the file's name, the server's URI).
TEST(PostgresStore, TheSameSessionExportsTheSameFilesFromBothBackEnds) {
  REQUIRE_POSTGRES(server);
  test::TempDir dir;
  testing::SmallStudy study(dir);
  const std::string file = dir.file("r.sqlite");
  for (const std::string& db : {file, server.location()}) {
    Session s = study.open("P01", db, 1'764'547'200'000);
    for (int i = 0; !s.finished(); ++i) {
      const std::int64_t t = 1'764'547'200'000 + 1000 * i;
      if (!s.current().stimuli.empty()) s.log_event(EventKind::play, s.current().stimuli.front(), t);
      s.answer(testing::good_answer(s), 123.456 + 0.1 * i, 1 + i % 3, t + 500);
    }
  }
  const auto a = export_results(file, dir.file("from-sqlite"));
  const auto b = export_results(server.location(), dir.file("from-postgres"));
  EXPECT_EQ(a.responses, 6u);
  EXPECT_EQ(a.responses, b.responses);
  EXPECT_EQ(a.tables, b.tables);
  std::size_t compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.file("from-sqlite"))) {
    const std::string name = entry.path().filename().string();
    const std::string mine = testing::file_text(entry.path().string());
    const std::string theirs = testing::file_text(dir.file("from-postgres/" + name));
    if (name == "study.json") {
      auto ja = nlohmann::json::parse(mine), jb = nlohmann::json::parse(theirs);
      EXPECT_EQ(ja["source"], "r.sqlite");
      EXPECT_EQ(jb["source"].get<std::string>().rfind("postgresql://", 0), 0u) << jb["source"];
      ja.erase("source");
      jb.erase("source");
      EXPECT_EQ(ja, jb);
    } else {
      EXPECT_FALSE(mine.empty()) << name;
      EXPECT_EQ(mine, theirs) << name;
    }
    ++compared;
  }
  EXPECT_GE(compared, 6u);  // responses, trials, events, study.json and the identify and mushra tables
}

}  // namespace
}  // namespace ms
