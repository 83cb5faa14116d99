// studyapp's command line: a missing or malformed protocol exits 2 with "studyapp: FILE..." lines (every
// problem), --autopilot runs headless (no display needed).
#include <QProcess>
#include <QProcessEnvironment>

#include <fstream>

#include "gui_fixture.hpp"

using namespace gui_test;

namespace {

struct RunResult {
  int code = -1;
  std::string out, err;
};

RunResult run_studyapp(const QStringList& args, bool with_display = false) {
  QProcess p;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  if (!with_display) {
    env.remove("DISPLAY");
    env.remove("WAYLAND_DISPLAY");
    env.remove("QT_QPA_PLATFORM");
  }
  p.setProcessEnvironment(env);
  p.start(STUDYAPP_BIN, args);
  if (!p.waitForFinished(300000)) {
    p.kill();
    p.waitForFinished();
  }
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput().toStdString(),
          p.readAllStandardError().toStdString()};
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
    out.push_back(text.substr(start, nl - start));
  if (start < text.size()) out.push_back(text.substr(start));
  return out;
}

}  // namespace

TEST(CommandLine, MissingProtocolExits2WithOneLine) {
  const RunResult r = run_studyapp({"no/such/protocol.yaml", "--participant", "P1"});
  EXPECT_EQ(r.code, 2);
  const auto l = lines(r.err);
  ASSERT_EQ(l.size(), 1u) << r.err;
  EXPECT_EQ(l[0].rfind("studyapp: no/such/protocol.yaml", 0), 0u) << l[0];
}

TEST(CommandLine, MalformedProtocolsExit2NamingEveryProblem) {
  const std::string dir = fresh_dir("cli-bad");
  const std::string path = dir + "/bad.yaml";
  std::ofstream(path) << "study: bad\nsample_rate: 44100\nseed: 1\nstimuli:\n  a: {paramset: nowhere.yaml}\n"
                         "blocks:\n  - {type: idntify, stimuli: [a], labels: [x]}\n  - {type: ab, pairs: [[a, zz]]}\n";
  const RunResult r = run_studyapp({QString::fromStdString(path), "--participant", "P1"});
  EXPECT_EQ(r.code, 2);
  const auto l = lines(r.err);
  EXPECT_GE(l.size(), 3u) << r.err;  // missing file, unknown block type, unknown stimulus
  for (const std::string& line : l) EXPECT_EQ(line.rfind("studyapp: " + path + ":", 0), 0u) << line;

  std::ofstream(dir + "/syntax.yaml") << "study: [unclosed\n";
  const RunResult s = run_studyapp({QString::fromStdString(dir + "/syntax.yaml")});
  EXPECT_EQ(s.code, 2);
  EXPECT_EQ(lines(s.err).size(), 1u) << s.err;
}

TEST(CommandLine, AutopilotWithoutProtocolExits2) {
  const RunResult r = run_studyapp({"--autopilot", "1"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(lines(r.err).size(), 1u) << r.err;
}

TEST(CommandLine, AutopilotRunsHeadlessWithoutADisplay) {
  const std::string dir = fresh_dir("cli-autopilot");
  const RunResult r = run_studyapp({QString::fromStdString(demo_protocol()), "--autopilot", "5", "--participant", "A1",
                              "--db", QString::fromStdString(dir + "/r.sqlite"), "--cache",
                              QString::fromStdString(shared_cache()), "--audio", "null"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("finished"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(dir + "/r.sqlite"), std::string::npos) << r.out;
}
