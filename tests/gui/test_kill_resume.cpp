// Process-level crash safety: studyapp --autopilot is SIGKILLed mid-session, then the same command is run
// again; it must resume the same session at the first unanswered trial with the same schedule, keep every
// answer given before the kill, and finish with exactly one answer per scheduled trial.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QProcess>

#include "gui_fixture.hpp"
#include "studyapp/core/results_store.hpp"

using namespace gui_test;

namespace {

std::int64_t responses_now(const std::string& db) {
  try {
    ms::ResultsStore store(db, ms::ResultsStore::Mode::read_only);
    return store.count("responses");
  } catch (const std::exception&) {
    return 0;  // not created yet
  }
}

}  // namespace

TEST(KillResume, SigkillMidSessionThenResumeLosesNothing) {
  const std::string dir = fresh_dir("kill");
  const std::string db = dir + "/r.sqlite";
  const std::vector<std::string> args{STUDYAPP_BIN, demo_protocol(), "--autopilot", "11", "--participant", "K1",
                                      "--db", db, "--cache", shared_cache()};
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    execv(argv[0], argv.data());
    _exit(127);
  }
  // Kill it as soon as some, but not all, answers are stored.
  std::int64_t seen = 0;
  int status = 0;
  bool exited = false;
  for (int i = 0; i < 300000 && seen < 3; ++i) {
    if (waitpid(pid, &status, WNOHANG) == pid) {
      exited = true;
      break;
    }
    seen = responses_now(db);
    if (seen < 3) usleep(500);
  }
  if (!exited) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
  }
  ASSERT_FALSE(exited) << "the autopilot finished before it could be killed";

  std::vector<ms::ResponseRow> before;
  std::int64_t trials_scheduled = 0;
  {
    ms::ResultsStore store(db, ms::ResultsStore::Mode::read_only);
    EXPECT_EQ(store.integrity_check(), "ok");
    before = store.response_rows();
    trials_scheduled = store.count("trials");
  }
  ASSERT_GE(before.size(), 3u);
  ASSERT_LT(static_cast<std::int64_t>(before.size()), trials_scheduled);

  QProcess again;
  QStringList qargs;
  for (std::size_t i = 1; i < args.size(); ++i) qargs << QString::fromStdString(args[i]);
  again.start(STUDYAPP_BIN, qargs);
  ASSERT_TRUE(again.waitForFinished(300000));
  EXPECT_EQ(again.exitCode(), 0) << again.readAllStandardError().toStdString();
  const std::string out = again.readAllStandardOutput().toStdString();
  EXPECT_NE(out.find("resumed"), std::string::npos) << out;

  ms::ResultsStore store(db, ms::ResultsStore::Mode::read_only);
  EXPECT_EQ(store.count("sessions"), 1);                 // the same session, not a new one
  EXPECT_EQ(store.count("trials"), trials_scheduled);     // the same schedule
  EXPECT_EQ(store.count("responses"), trials_scheduled);  // one answer per trial
  const auto after = store.response_rows();
  for (const ms::ResponseRow& b : before) {  // every answer from before the kill, unchanged
    const auto same = std::find_if(after.begin(), after.end(), [&](const ms::ResponseRow& a) {
      return a.block_index == b.block_index && a.trial_index == b.trial_index;
    });
    ASSERT_NE(same, after.end());
    EXPECT_EQ(same->value_json, b.value_json);
    EXPECT_EQ(same->timestamp_ms, b.timestamp_ms);
  }
}
