// The export against spreadsheet formula injection (OWASP: a leading single quote on cells starting
// with = + - @ TAB CR, numbers left alone), its session and autopilot columns, and the `stats` input
// options (--exclude-autopilot, --where, the several-sessions warning) on what it wrote.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "synthesis/tidy_csv.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/results_store.hpp"
#include "support/test_util.hpp"

using namespace ms;

namespace {

constexpr std::int64_t kT0 = 1'700'000'000'000;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// One participant whose code is a formula, in two sessions; questionnaire answers that are formulas
// or numbers; identification answers.
std::string build_db(const test::TempDir& dir) {
  const std::string path = dir.file("inj.sqlite");
  ResultsStore store(path);
  store.add_study({"inj", "Injection", std::string(64, 'e'),
                   "study: inj\ntitle: Injection\nstimuli:\n  metal: {file: m.wav}\n  glass: {file: g.wav}\n"
                   "blocks:\n  - {type: identify, id: id, stimuli: [metal, glass], labels: [metal, glass]}\n"
                   "  - {type: questionnaire, id: q, questions: [{id: age, text: Age}, {id: note, text: Note}]}\n",
                   true});
  const auto p = store.add_participant("inj", "=HYPERLINK(\"http://x\",\"y\")", kT0);
  for (int s = 0; s < 2; ++s) {
    const auto session = store.start_session(p, kT0 + s * 1000, 7u);
    store.record_trials(session, {{0, "id", "identify", 0, {"metal"}, {"h1"}},
                                  {0, "id", "identify", 1, {"glass"}, {"h2"}},
                                  {1, "q", "questionnaire", 0, {}, {}}});
    store.record_response(session, {{0, 0}, "\"metal\"", 800, 1, kT0 + s * 1000 + 1});
    store.record_response(session, {{0, 1}, "\"metal\"", 900, 1, kT0 + s * 1000 + 2});
    store.record_response(session, {{1, 0}, R"({"age":"-3","note":"=1+2"})", 5000, 0, kT0 + s * 1000 + 3});
  }
  return path;
}

}  // namespace

TEST(ExportInjection, FormulasNeutralisedNumbersKept) {
  test::TempDir dir;
  export_results(build_db(dir), dir.file("out"));
  const std::string q = slurp(dir.file("out/questionnaire.csv"));
  EXPECT_NE(q.find(",\"'=1+2\""), std::string::npos) << q;
  EXPECT_EQ(q.find(",=1+2"), std::string::npos) << q;
  EXPECT_NE(q.find(",-3\r\n"), std::string::npos) << q;  // a number stays a number
  const TidyCsv t = TidyCsv::read(dir.file("out/questionnaire.csv"));
  ASSERT_EQ(t.rows(), 4u);
  EXPECT_EQ(t.cell(0, t.column("answer")), "-3");
  EXPECT_EQ(t.cell(1, t.column("answer")), "'=1+2");
  // The personal code (export_personal: true) in every file that carries it.
  for (const char* f : {"responses.csv", "identify.csv", "questionnaire.csv", "trials.csv"}) {
    const std::string text = slurp(dir.file(std::string("out/") + f));
    EXPECT_EQ(text.find(",=HYPERLINK"), std::string::npos) << f;
    EXPECT_NE(text.find(",\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\""), std::string::npos) << f << "\n" << text;
  }
}

TEST(ExportInjection, SessionsWarnedAutopilotAndWhereSelect) {
  test::TempDir dir;
  export_results(build_db(dir), dir.file("out"));
  const TidyCsv id = TidyCsv::read(dir.file("out/identify.csv"));
  ASSERT_EQ(id.rows(), 4u);
  EXPECT_EQ(id.cell(0, id.column("session")), "1");
  EXPECT_EQ(id.cell(2, id.column("session")), "2");
  EXPECT_EQ(id.cell(0, id.column("autopilot")), "0");
  // Two sessions of one participant: one warning line on stderr, and the statistic still runs.
  const std::string args = "stats confusion " + dir.file("out/identify.csv") + " --truth truth --response response";
  const auto both = test::run_cli(args + " --json", dir);
  ASSERT_EQ(both.exit_code, 0) << both.err;
  EXPECT_EQ(test::count_lines(both.err), 1u) << both.err;
  EXPECT_NE(both.err.find("warning: "), std::string::npos);
  EXPECT_NE(both.err.find("1 participant(s) answered in more than one session"), std::string::npos) << both.err;
  // --where session=2 keeps one session: no warning; --exclude-autopilot keeps the human sessions.
  const auto one = test::run_cli(args + " --where session=2 --json", dir);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_TRUE(one.err.empty()) << one.err;
  const auto human = test::run_cli(args + " --exclude-autopilot --json", dir);
  ASSERT_EQ(human.exit_code, 0) << human.err;
  // A table without the autopilot column: the flag is refused, naming the file.
  const std::string old = dir.write("old.csv", "participant,truth,response\np1,a,a\np1,b,a\n");
  const auto refused =
      test::run_cli("stats confusion " + old + " --truth truth --response response --exclude-autopilot", dir);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find(old + ":1:1: --exclude-autopilot: the table has no column 'autopilot'"),
            std::string::npos)
      << refused.err;
  const auto bad_where = test::run_cli(args + " --where nosuch=1", dir);
  EXPECT_EQ(bad_where.exit_code, 2);
  EXPECT_NE(bad_where.err.find("missing column 'nosuch'"), std::string::npos) << bad_where.err;
}
