// The results store as a lab meets it at its worst: a kill or a full disk while the file is created,
// a participant who already finished, the same participant started in two processes, a damaged file,
// a folder SQLite cannot write in, ids typed with stray spaces or another case, simulated sessions.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <pwd.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "core_fixtures.hpp"
#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/participant_id.hpp"
#include "studyapp/core/participant_status.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/results_store.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/core/sqlite_handle.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "support/test_stores.hpp"
#include "synthesis/input_error.hpp"

namespace ms {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

nlohmann::json good_answer(const Session& s) {
  const Trial& t = s.current();
  if (t.type == BlockType::instructions) return "ok";
  if (t.type == BlockType::identify) return t.stimuli.at(0);
  nlohmann::json v = nlohmann::json::object();
  for (const auto& name : t.stimuli) v[name] = 50;
  return v;
}

// A store with one answered session, closed (so its log is checkpointed into the main file).
void fill_store(const std::string& path) {
  ResultsStore store(path);
  store.add_study({"demo", "Demo", std::string(64, 'a'), "study: demo\n", false});
  for (int p = 0; p < 3; ++p) {
    const auto pid = store.add_participant("demo", "P0" + std::to_string(p), 1000);
    const auto s = store.start_session(pid, 1000, 7u);
    std::vector<TrialRecord> trials;
    for (int i = 0; i < 20; ++i) trials.push_back({0, "id", "identify", i, {"s"}, {"h"}});
    store.record_trials(s, trials);
    for (int i = 0; i < 20; ++i) store.record_response(s, {{0, i}, "\"metal\"", 100.0, 1, 1000 + i});
  }
}

TEST(StoreSafety, AKillAtAnyMomentOfCreationLeavesAStoreTheNextRunCompletes) {
  test::TempDir dir;
  const std::string path = dir.file("r.sqlite");
  for (int attempt = 0; attempt < 40; ++attempt) {
    fs::remove(path);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      try {
        fill_store(path);
      } catch (...) {
      }
      ::_exit(0);
    }
    ::usleep(useconds_t(250 * attempt));  // from 0 to 10 ms: through creation and the first writes
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    // The next run opens (or creates) the store and completes a session in it.
    ResultsStore store(path);
    EXPECT_EQ(store.integrity_check(), "ok") << "attempt " << attempt;
    store.add_study({"next", "Next", std::string(64, 'b'), "study: next\n", false});
    const auto s = store.start_session(store.add_participant("next", "N1", 1), 1, 1u);
    store.record_trials(s, {{0, "id", "identify", 0, {"s"}, {"h"}}});
    store.record_response(s, {{0, 0}, "1", 1.0, 1, 1});
    EXPECT_EQ(store.first_unanswered_trial(s), std::nullopt);
  }
  // No temporary file of a killed creation is left behind once a later creation ran.
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_FALSE(contains(e.path().filename().string(), ".new-")) << e.path();
}

TEST(StoreSafety, AnEmptyFileLeftByAnInterruptedCreationIsTreatedAsNew) {
  test::TempDir dir;
  const std::string path = dir.write("r.sqlite", "");
  dir.write("r.sqlite-journal", std::string(512, '\x5a'));  // debris beside it must not be replayed
  ResultsStore store(path);
  EXPECT_EQ(store.integrity_check(), "ok");
  EXPECT_EQ(store.schema_version(), ResultsStore::kSchemaVersion);
}

// A server opening many participants' sessions at once into a store not yet created: every thread
// gets the one database (they once shared a temporary file, named by the process id).
TEST(StoreSafety, ThreadsCreatingOneStoreAtOnceAllOpenIt) {
  for (int round = 0; round < 10; ++round) {
    test::TempDir dir;
    const std::string path = dir.file("r.sqlite");
    constexpr int kThreads = 24;
    std::atomic<int> ready{0}, opened{0};
    std::vector<std::string> failures(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&, t] {
        ++ready;
        while (ready < kThreads) std::this_thread::yield();
        try {
          ResultsStore store(path);
          ++opened;
        } catch (const std::exception& e) {
          failures[std::size_t(t)] = e.what();
        }
      });
    for (std::thread& t : threads) t.join();
    for (const std::string& f : failures) EXPECT_EQ(f, "");
    ASSERT_EQ(opened, kThreads) << "round " << round;
  }
}

TEST(StoreSafety, AFullDiskAtCreationLeavesNoFileAndTheNextRunCreatesIt) {
  test::TempDir dir;
  const std::string path = dir.file("r.sqlite");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);  // writes past the limit fail with EFBIG, as on a full disk
    const rlimit small{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &small);
    try {
      ResultsStore store(path);
    } catch (const InputError& e) {
      ::_exit(contains(e.what(), "cannot create the results database") ? 3 : 4);
    } catch (...) {
      ::_exit(5);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);
  EXPECT_FALSE(fs::exists(path));
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_FALSE(contains(e.path().filename().string(), "r.sqlite")) << e.path();
  ResultsStore store(path);
  EXPECT_EQ(store.integrity_check(), "ok");
}

// The rules of sessions and leases, on both back ends.
class StoreSafetyOnBoth : public ::testing::TestWithParam<test::Backend> {};
INSTANTIATE_TEST_SUITE_P(Backends, StoreSafetyOnBoth,
                         ::testing::Values(test::Backend::sqlite, test::Backend::postgresql), test::backend_name);

TEST_P(StoreSafetyOnBoth, AFinishedParticipantIsRefusedUnlessANewSessionIsAsked) {
  test::TestStore where(GetParam());
  SKIP_WITHOUT_STORE(where);
  const std::string path = testing::write_small_study(where.dir());
  const Protocol p = load_protocol(path);
  StimulusCache cache(p, "");
  const std::string db = where.location();
  {
    Session s(p, slurp(path), "P07", db, cache.hashes(), 1'764'547'200'000);  // 2025-12-01
    while (!s.finished()) s.answer(good_answer(s), 1.0, 1, 1'764'547'200'000);
  }
  try {
    Session again(p, slurp(path), "P07", db, cache.hashes(), 1'764'633'600'000);
    FAIL() << "a finished participant was run again";
  } catch (const ParticipantFinished& e) {
    EXPECT_TRUE(contains(e.what(), "P07 finished this study on 2025-12-01 (6/6 trials); use --new-session"))
        << e.what();
  }
  const ParticipantStatus status = participant_status(db, "small", "P07");
  EXPECT_EQ(status.state, ParticipantStatus::State::finished);
  EXPECT_EQ(describe(status), "P07 finished this study on 2025-12-01 (6/6 trials)");
  Session second(p, slurp(path), "P07", db, cache.hashes(), 1'764'633'600'000, SessionStart{true, false});
  EXPECT_FALSE(second.resumed());
  EXPECT_EQ(second.current_index(), 0u);
  EXPECT_EQ(second.store().count("sessions"), 2);
}

TEST(StoreSafety, ParticipantIdsAreTrimmedAndLookAlikesAreNamed) {
  EXPECT_EQ(normalize_participant_id("  P07 \t"), "P07");
  EXPECT_THROW(normalize_participant_id("   "), InputError);
  EXPECT_THROW(normalize_participant_id("P\x01"), InputError);
  EXPECT_EQ(look_alike_ids("p 07", {"P07", "P08", "p 07"}), std::vector<std::string>{"P07"});

  test::TempDir dir;
  const std::string path = testing::write_small_study(dir);
  const Protocol p = load_protocol(path);
  StimulusCache cache(p, "");
  const std::string db = dir.file("r.sqlite");
  {
    Session s(p, slurp(path), "P07 ", db, cache.hashes(), 1000);
    s.answer(good_answer(s), 1.0, 1, 1000);
    EXPECT_EQ(s.participant(), "P07");
    EXPECT_TRUE(s.warnings().empty());
  }
  Session same(p, slurp(path), " P07", db, cache.hashes(), 2000);
  EXPECT_TRUE(same.resumed());  // the same participant, not a second one
  EXPECT_EQ(same.current_index(), 1u);
  {
    Session other(p, slurp(path), "p07", db, cache.hashes(), 3000);
    ASSERT_EQ(other.warnings().size(), 1u);
    EXPECT_TRUE(contains(other.warnings()[0], "'p07' differs only by case or spaces from 'P07'"))
        << other.warnings()[0];
  }
  EXPECT_THROW(Session(p, slurp(path), "  ", db, cache.hashes(), 4000), InputError);
}

// The child opens P01's session and holds it until told to go (or is killed); `ready` and `go` are pipes.
pid_t hold_session_in_child(const std::string& study_path, const std::string& db, int ready, int go) {
  const pid_t child = ::fork();
  if (child != 0) return child;
  try {
    const Protocol p = load_protocol(study_path);
    StimulusCache cache(p, "");
    Session s(p, slurp(study_path), "P01", db, cache.hashes(), unix_now_ms());
    s.answer(good_answer(s), 1.0, 1, unix_now_ms());
    (void)!::write(ready, "r", 1);
    char c = 0;
    (void)!::read(go, &c, 1);
  } catch (...) {
    ::_exit(4);
  }
  ::_exit(0);
}

TEST_P(StoreSafetyOnBoth, TheSameParticipantInTwoProcessesIsRefusedAndACrashDoesNotBlockTheResume) {
  test::TestStore where(GetParam());
  SKIP_WITHOUT_STORE(where);
  const std::string path = testing::write_small_study(where.dir());
  const std::string db = where.location();
  int ready[2], go[2];
  ASSERT_EQ(::pipe(ready), 0);
  ASSERT_EQ(::pipe(go), 0);
  const pid_t child = hold_session_in_child(path, db, ready[1], go[0]);
  char c = 0;
  ASSERT_EQ(::read(ready[0], &c, 1), 1);

  const Protocol p = load_protocol(path);
  StimulusCache cache(p, "");
  try {
    Session second(p, slurp(path), "P01", db, cache.hashes(), unix_now_ms());
    FAIL() << "two processes ran one participant";
  } catch (const SessionInUse& e) {
    EXPECT_TRUE(contains(e.what(), "participant 'P01' is being run right now by pid " + std::to_string(child)))
        << e.what();
  }
  {  // another participant on the same file is not held up
    Session other(p, slurp(path), "P02", db, cache.hashes(), unix_now_ms());
    while (!other.finished()) other.answer(good_answer(other), 1.0, 1, unix_now_ms());
  }
  ::kill(child, SIGKILL);  // the booth crashes; its lease stays in the file
  int status = 0;
  ::waitpid(child, &status, 0);
  Session resumed(p, slurp(path), "P01", db, cache.hashes(), unix_now_ms());
  EXPECT_TRUE(resumed.resumed());
  EXPECT_EQ(resumed.current_index(), 1u);
  while (!resumed.finished()) resumed.answer(good_answer(resumed), 1.0, 1, unix_now_ms());
  EXPECT_EQ(resumed.store().count("responses"), 12);
  EXPECT_EQ(resumed.store().count("sessions"), 2);
}

TEST_P(StoreSafetyOnBoth, AProcessWhoseLeaseWasTakenOverStoresNothingMore) {
  test::TestStore where(GetParam());
  SKIP_WITHOUT_STORE(where);
  const std::string db = where.location();
  ResultsStore store(db);
  store.add_study({"demo", "Demo", std::string(64, 'a'), "study: demo\n", false});
  SessionRequest r{"demo", "P01", 1000, 7u, {{0, "id", "identify", 0, {"s"}, {"h"}}, {0, "id", "identify", 1, {"s"}, {"h"}}}};
  r.holder = {"booth-2", 4242, "77"};  // another host took the session over after our lease went stale
  const OpenedSession o = store.open_session({"demo", "Demo", std::string(64, 'a'), "study: demo\n", false}, r);
  try {
    store.record_response(o.session, {{0, 0}, "1", 1.0, 1, 2000});
    FAIL() << "wrote into a session another process holds";
  } catch (const SessionInUse& e) {
    EXPECT_TRUE(contains(e.what(), "is now run by pid 4242 on booth-2")) << e.what();
  }
  EXPECT_EQ(store.count("responses"), 0);
  EXPECT_FALSE(lease_is_stale(r.holder, 1000, 1000 + kLeaseTimeoutMs));
  EXPECT_TRUE(lease_is_stale(r.holder, 1000, 1001 + kLeaseTimeoutMs));
  EXPECT_FALSE(lease_is_stale(this_process(), 0, 1'000'000'000'000));  // alive here, however old
}

TEST(StoreSafety, AKilledProcessNotYetReapedHoldsNoLease) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  ::usleep(50'000);  // the child is a zombie now: dead, but its pid is not reaped yet
  EXPECT_EQ(process_start_time(child), "");
  EXPECT_TRUE(lease_is_stale({this_process().host, child, "1"}, 0, 0));
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_NE(process_start_time(::getpid()), "");
}

TEST(StoreSafety, ADamagedFileIsRefusedByNameAndNeverWritten) {
  test::TempDir dir;
  const std::string db = dir.file("r.sqlite");
  fill_store(db);
  ASSERT_FALSE(fs::exists(db + "-wal"));  // checkpointed into the main file on close
  {  // garbage over the participants table's page (page 4: after the schema, version and studies)
    std::fstream f(db, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(3 * 4096);
    const std::string junk(200, '\x7f');
    f.write(junk.data(), std::streamsize(junk.size()));
  }
  const std::string before = slurp(db);
  for (auto mode : {ResultsStore::Mode::create_or_open, ResultsStore::Mode::open_existing, ResultsStore::Mode::read_only})
    try {
      ResultsStore store(db, mode);
      FAIL() << "a damaged file was opened";
    } catch (const InputError& e) {
      EXPECT_TRUE(contains(e.what(), db + ": the results database is damaged")) << e.what();
      EXPECT_TRUE(contains(e.what(), ".recover")) << e.what();
    }
  try {
    export_results(db, dir.file("out"));
    FAIL() << "a damaged file was exported";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "damaged")) << e.what();
  }
  EXPECT_EQ(slurp(db), before);  // not one byte written
  EXPECT_FALSE(fs::exists(dir.file("out/responses.csv")));
}

TEST(StoreSafety, AnExportNeverReportsSuccessOverMissingRows) {
  test::TempDir dir;
  const std::string db = dir.file("r.sqlite");
  fill_store(db);
  {  // a participant row lost (the file passes its integrity check: only the rows are gone)
    sqlite::Database raw(db, 0x2 /* SQLITE_OPEN_READWRITE */);
    raw.exec("PRAGMA foreign_keys=OFF; DELETE FROM participants WHERE code = 'P01'");
  }
  try {
    export_results(db, dir.file("out"));
    FAIL() << "exported with rows missing";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "responses holds 60 rows but only 40")) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir.file("out/responses.csv")));
}

TEST(StoreSafety, AFolderSQLiteCannotWriteInIsNamedAsSuch) {
  test::TempDir dir;
  fs::create_directories(dir.file("locked"));
  const std::string db = dir.file("locked/r.sqlite");
  fill_store(db);
  ::chmod(dir.file("locked").c_str(), 0555);
  ::chmod(db.c_str(), 0644);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // root writes anywhere: run as an ordinary user, as a lab's account would
    if (::geteuid() == 0) {
      const passwd* nobody = ::getpwnam("nobody");
      if (!nobody || ::setgid(nobody->pw_gid) != 0 || ::setuid(nobody->pw_uid) != 0) ::_exit(9);
    }
    try {
      ResultsStore store(db);
    } catch (const InputError& e) {
      ::_exit(contains(e.what(), "no permission to write in folder") && !contains(e.what(), "not a ModalStudy") ? 0 : 3);
    } catch (...) {
      ::_exit(4);
    }
    ::_exit(5);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ::chmod(dir.file("locked").c_str(), 0755);
  ASSERT_TRUE(WIFEXITED(status));
  if (WEXITSTATUS(status) == 9) GTEST_SKIP() << "no unprivileged user to run as";
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST_P(StoreSafetyOnBoth, SimulatedSessionsAreMarked) {
  test::TestStore where(GetParam());
  SKIP_WITHOUT_STORE(where);
  const std::string path = testing::write_small_study(where.dir());
  AutopilotOptions o;
  o.protocol_path = path;
  o.db_path = where.location();
  o.participant = "A1";
  run_autopilot(o);
  {
    const Protocol p = load_protocol(path);
    StimulusCache cache(p, "");
    Session human(p, slurp(path), "H1", o.db_path, cache.hashes(), 1000);
    while (!human.finished()) human.answer(good_answer(human), 1.0, 1, 1000);
  }
  const ResultsStore store(o.db_path, ResultsStore::Mode::read_only);
  for (const auto& s : store.session_summaries()) EXPECT_EQ(s.autopilot, s.participant_code == "A1");
  int simulated = 0;
  for (const auto& r : store.response_rows()) simulated += r.autopilot ? 1 : 0;
  EXPECT_EQ(simulated, 6);
  EXPECT_EQ(store.count("responses"), 12);
}

TEST(StoreSafety, AVersionOneFileIsReadAsItIsAndMigratedWhenWritten) {
  test::TempDir dir;
  const std::string db = dir.file("r.sqlite");
  fill_store(db);
  {  // back to the first schema
    sqlite::Database raw(db, 0x2);
    raw.exec("DROP TABLE leases; ALTER TABLE sessions DROP COLUMN autopilot; UPDATE schema_version SET version = 1");
  }
  {
    const ResultsStore old(db, ResultsStore::Mode::read_only);
    EXPECT_EQ(old.schema_version(), 1);
    EXPECT_EQ(old.response_rows().size(), 60u);
    EXPECT_FALSE(old.session_summaries().front().autopilot);
  }
  ResultsStore store(db);
  EXPECT_EQ(store.schema_version(), 2);
  EXPECT_EQ(store.count("leases"), 0);
  EXPECT_EQ(store.response_rows().size(), 60u);
}

}  // namespace
}  // namespace ms
