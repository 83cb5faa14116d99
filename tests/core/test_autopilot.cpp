// The autopilot runs whole sessions headless: the demo protocol end to end (then export and the
// statistics read the tidy tables), sensible simulated answers, and a session killed with SIGKILL
// mid-way resumes at the first unanswered trial losing nothing.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core_fixtures.hpp"
#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/results_store.hpp"
#include "synthesis/tidy_csv.hpp"
#include "synthesis/input_error.hpp"

namespace ms {
namespace {

const std::string kDemo = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/demo.yaml";

TEST(Autopilot, RunsTheDemoEndToEndThenExportAndStatistics) {
  test::TempDir dir;
  AutopilotOptions o;
  o.protocol_path = kDemo;
  o.participant = "P01";
  o.db_path = dir.file("demo.sqlite");
  o.cache_dir = dir.file("cache");
  o.seed = 3;
  const AutopilotSummary s = run_autopilot(o);
  EXPECT_TRUE(s.finished);
  EXPECT_FALSE(s.resumed);
  EXPECT_EQ(s.answered_now, s.total);
  {
    ResultsStore store(o.db_path, ResultsStore::Mode::read_only);
    EXPECT_EQ(store.count("responses"), std::int64_t(s.total));
    EXPECT_EQ(store.integrity_check(), "ok");
  }
  const ExportSummary e = export_results(o.db_path, dir.file("out"));
  EXPECT_EQ(e.responses, s.total);
  for (const char* table : {"ab.csv", "mushra.csv", "magnitude.csv", "identify.csv", "rating.csv", "adjust.csv",
                            "staircase.csv", "questionnaire.csv"})
    EXPECT_NE(std::find(e.tables.begin(), e.tables.end(), table), e.tables.end()) << table;
  EXPECT_TRUE(std::filesystem::exists(dir.file("out/events.csv")));
  // Every event names the recipe hash of the stimulus it played (when the trial lists it).
  const TidyCsv events = TidyCsv::read(dir.file("out/events.csv"));
  ASSERT_GT(events.rows(), 0u);
  std::size_t hashed = 0;
  for (std::size_t r = 0; r < events.rows(); ++r) hashed += events.cell(r, events.column("stimulus_hash")).size() == 64;
  EXPECT_GT(hashed, events.rows() / 2);

  // The statistics read the tidy tables directly.
  const auto mushra = test::run_cli("stats mushra " + dir.file("out/mushra.csv") + " --reference full --json", dir);
  EXPECT_EQ(mushra.exit_code, 0) << mushra.err;
  const auto ident = test::run_cli(
      "stats confusion " + dir.file("out/identify.csv") + " --truth stimulus --response response --json", dir);
  EXPECT_EQ(ident.exit_code, 0) << ident.err;
  const auto stair = test::run_cli("stats staircase " + dir.file("out/staircase.csv") +
                                       " --level level --track participant --track block --trial step --json", dir);
  EXPECT_EQ(stair.exit_code, 0) << stair.err;
}

TEST(Autopilot, SimulatedAnswersFollowThePerceptualDistance) {
  test::TempDir dir;
  // Identification of two clearly different sounds, and MUSHRA: the hidden reference must win.
  const std::string path = testing::write_small_study(dir);
  AutopilotOptions o;
  o.protocol_path = path;
  o.db_path = dir.file("r.sqlite");
  for (int p = 0; p < 4; ++p) {
    o.participant = "P" + std::to_string(p);
    run_autopilot(o);
  }
  ResultsStore store(o.db_path, ResultsStore::Mode::read_only);
  int identify = 0, correct = 0, mushra = 0;
  for (const auto& row : store.response_rows()) {
    const auto v = nlohmann::json::parse(row.value_json);
    const auto stim = nlohmann::json::parse(row.stimuli_json);
    if (row.block_type == "identify") {
      ++identify;
      correct += v == stim[0];
    } else if (row.block_type == "mushra") {
      ++mushra;
      EXPECT_GE(v["low"].get<double>(), 85.0) << row.value_json;  // the hidden reference
      EXPECT_GT(v["low"].get<double>(), v["lp"].get<double>()) << row.value_json;
    }
  }
  EXPECT_EQ(identify, 16);
  EXPECT_EQ(mushra, 4);
  EXPECT_GE(correct, 15);  // 440 vs 880 Hz: nearly always right
}

TEST(Autopilot, KilledMidSessionResumesLosingNothing) {
  test::TempDir dir;
  const std::string db = dir.file("kill.sqlite");
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(fds[0]);
    AutopilotOptions o;
    o.protocol_path = kDemo;
    o.participant = "K1";
    o.db_path = db;
    o.cache_dir = dir.file("cache");
    run_autopilot(o, [&](const std::string& line) {
      if (line.rfind("answered", 0) == 0) (void)!::write(fds[1], "a", 1);  // after the commit
    });
    ::_exit(0);
  }
  ::close(fds[1]);
  constexpr int kBeforeKill = 5;
  int reported = 0;
  char c;
  while (reported < kBeforeKill && ::read(fds[0], &c, 1) == 1) ++reported;
  ASSERT_EQ(::kill(child, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ::close(fds[0]);
  ASSERT_EQ(reported, kBeforeKill);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the session ended before the kill";

  std::int64_t stored = 0;
  {
    ResultsStore store(db);
    EXPECT_EQ(store.integrity_check(), "ok");
    stored = store.count("responses");
  }
  EXPECT_GE(stored, kBeforeKill);  // every acknowledged answer survived
  AutopilotOptions o;
  o.protocol_path = kDemo;
  o.participant = "K1";
  o.db_path = db;
  o.cache_dir = dir.file("cache");
  const AutopilotSummary s = run_autopilot(o);
  EXPECT_TRUE(s.resumed);
  EXPECT_TRUE(s.finished);
  EXPECT_EQ(s.answered_now + std::size_t(stored), s.total);  // resumed at the first unanswered trial
  ResultsStore store(db, ResultsStore::Mode::read_only);
  EXPECT_EQ(store.count("responses"), std::int64_t(s.total));
  EXPECT_EQ(store.count("sessions"), 1);
}

TEST(Autopilot, AnInvalidProtocolListsEveryProblem) {
  test::TempDir dir;
  const std::string path = dir.write("bad.yaml", "study: bad\nstimuli:\n  a: {paramset: missing.yaml}\nblocks:\n"
                                                 "  - {type: identfy, stimuli: [a]}\n  - {type: mushra, conditions: [a]}\n");
  AutopilotOptions o;
  o.protocol_path = path;
  o.db_path = dir.file("r.sqlite");
  try {
    run_autopilot(o);
    FAIL() << "expected InputError";
  } catch (const InvalidProtocol& e) {
    ASSERT_EQ(e.problems().size(), 3u);  // missing file, unknown type, MUSHRA without reference
    EXPECT_NE(e.problems()[0].find("bad.yaml:3:"), std::string::npos) << e.problems()[0];
    EXPECT_NE(e.problems()[1].find("did you mean 'identify'"), std::string::npos) << e.problems()[1];
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);  // what() stays one line
  }
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.sqlite")));    // nothing written
}

}  // namespace
}  // namespace ms
