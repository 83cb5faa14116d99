// A whole demo session (protocols/demo.yaml, --audio null) driven through the real views with QTest
// clicks and keys; then every response must be in the database and `modalstudy export` must read it.
#include <QProcess>

#include <algorithm>
#include <fstream>

#include "gui_fixture.hpp"
#include "studyapp/core/results_store.hpp"

using namespace gui_test;

namespace {

std::size_t count_lines(const std::string& path) {
  std::ifstream in(path);
  return static_cast<std::size_t>(std::count(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>(), '\n'));
}

}  // namespace

TEST(SessionDrive, WholeDemoSessionThroughTheViews) {
  const std::string dir = fresh_dir("drive");
  const std::string db = dir + "/results.sqlite";
  ms::gui::MainWindow w(demo_options("P01", db));
  ASSERT_TRUE(start_window(w));
  const std::size_t total = w.controller()->session().total();
  DriveLog log;
  ASSERT_TRUE(drive(w, log));

  // Every block type was shown and answered; the demo has one break (identify, break_after: 2).
  EXPECT_EQ(log.seen.size(), ms::block_type_names().size());
  EXPECT_EQ(static_cast<std::size_t>(log.trials), total);
  EXPECT_GE(log.breaks, 1);
  EXPECT_GT(log.staircase_steps, 2);
  EXPECT_EQ(log.limits_steps, 3);  // "same", "same", "different": the series ends at the first change
  EXPECT_EQ(log.tokens_steps, 5);  // from 6 to 1 modes: every token below the first compared once
  EXPECT_EQ(log.marks_before_hearing, 0);  // a change can be marked only at a sound heard
  EXPECT_TRUE(log.used_keys) << "Enter did not act as Next";
  std::size_t gated = 0;  // every trial with sounds waits until every sound was heard (listen_all default)
  for (const ms::Trial& t : w.controller()->session().schedule().trials)
    gated += t.type != ms::BlockType::instructions && t.type != ms::BlockType::questionnaire;
  EXPECT_EQ(log.listen_rule.size(), gated);
  ASSERT_EQ(log.resynth_ms.size(), 5u);

  // Every response is stored, with play events.
  {
    ms::ResultsStore store(db, ms::ResultsStore::Mode::read_only);
    EXPECT_EQ(store.count("responses"), static_cast<std::int64_t>(total));
    EXPECT_EQ(store.count("sessions"), 1);
    EXPECT_GT(store.count("events"), static_cast<std::int64_t>(total));
    EXPECT_FALSE(store.first_unanswered_trial(w.controller()->session().id()).has_value());
    for (const ms::ResponseRow& r : store.response_rows()) {
      if (r.block_type == "instructions" || r.block_type == "questionnaire") continue;
      EXPECT_GT(r.plays, 0) << r.block_id << " trial " << r.trial_index;
      EXPECT_GT(r.rt_ms, 0.0);
    }
  }

  // The command line exports it.
  QProcess exporter;
  exporter.start(MODALSTUDY_BIN, {"export", QString::fromStdString(db), "-o", QString::fromStdString(dir + "/export")});
  ASSERT_TRUE(exporter.waitForFinished(60000));
  EXPECT_EQ(exporter.exitCode(), 0) << exporter.readAllStandardError().toStdString();
  EXPECT_EQ(count_lines(dir + "/export/responses.csv"), total + 1);  // header + one row per response
}

TEST(SessionDrive, AdjustResynthesisesWithin50msOfASliderMove) {
  const std::string dir = fresh_dir("adjust");
  ms::gui::AppOptions options = demo_options("P02", dir + "/results.sqlite");
  options.cache_dir = dir + "/cache";  // empty: each slider position is synthesised, not read back from disk
  ms::gui::MainWindow w(options);
  ASSERT_TRUE(start_window(w));
  DriveLog log;
  // Answer up to the adjust trial, then measure ten moves there.
  drive(w, log, 1000, {}, ms::BlockType::adjust);
  ASSERT_TRUE(w.trial_view());
  ASSERT_EQ(w.controller()->session().current().type, ms::BlockType::adjust);
  QWidget* view = w.trial_view();
  ASSERT_TRUE(wait_until([&] { return view->property("renders").toInt() >= 1; }));
  auto* slider = children_with_prefix<QSlider>(view, "adjust-")[0];
  // The demo's set writes damping.alpha1 = 2.3 on the slider's [0.5, 10]: it starts there, not mid-range.
  EXPECT_EQ(slider->value(), 19);
  std::vector<double> ms_per_move;
  for (int move = 0; move < 10; ++move) {
    const int before = view->property("renders").toInt();
    QTest::keyClick(slider, move % 2 ? Qt::Key_PageUp : Qt::Key_Right);  // always new values
    ASSERT_TRUE(wait_until([&] { return view->property("renders").toInt() > before; }));
    ms_per_move.push_back(view->property("resynth_ms").toDouble());
  }
  std::sort(ms_per_move.begin(), ms_per_move.end());
  const double median = ms_per_move[ms_per_move.size() / 2];
  std::printf("adjust re-synthesis, slider move -> new sound ready: median %.1f ms, max %.1f ms over %zu moves\n", median,
              ms_per_move.back(), ms_per_move.size());
  EXPECT_LT(median, 50.0);
  // Each play of a variant is logged with its slider values and recipe hash.
  w.controller()->play(0);
  bool logged = false;
  for (const auto& e : w.controller()->session().store().event_rows())
    logged = logged || (e.block_type == "adjust" && e.detail_json.find("damping.alpha1") != std::string::npos &&
                        e.detail_json.find("\"hash\"") != std::string::npos);
  EXPECT_TRUE(logged);
}

TEST(SessionDrive, ClosingMidSessionResumesAtTheFirstUnansweredTrial) {
  const std::string dir = fresh_dir("resume");
  const std::string db = dir + "/results.sqlite";
  std::size_t answered = 0;
  std::vector<std::string> order;
  {
    ms::gui::MainWindow w(demo_options("P03", db));
    ASSERT_TRUE(start_window(w));
    for (const ms::Trial& t : w.controller()->session().schedule().trials) order.push_back(t.block_id);
    DriveLog log;
    drive(w, log, 4);
    answered = w.controller()->session().answered();
    ASSERT_EQ(answered, 4u);
  }
  ms::gui::MainWindow again(demo_options("P03", db));
  ASSERT_TRUE(start_window(again));
  ms::Session& s = again.controller()->session();
  EXPECT_TRUE(s.resumed());
  EXPECT_EQ(s.answered(), answered);
  EXPECT_EQ(s.current_index(), answered);
  std::vector<std::string> order_again;
  for (const ms::Trial& t : s.schedule().trials) order_again.push_back(t.block_id);
  EXPECT_EQ(order_again, order);
  auto* notice = again.findChild<QLabel*>("resumedNotice");
  ASSERT_NE(notice, nullptr);
  EXPECT_TRUE(notice->isVisible());
  EXPECT_TRUE(notice->text().contains("trial 5 of")) << notice->text().toStdString();
}

// The shipped replications with few trials, whole sessions through the same views: the A/B comparison
// with a reference per pair (bipolar -3..+3), the five-material identification and the Q sweeps of
// change points (10 trials of 19 sounds), and the bounce sequences of sound variation (16 pairs).
class ShippedProtocol : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedProtocol, WholeSessionThroughTheViews) {
  const std::string name = GetParam();
  const std::string dir = fresh_dir("shipped-" + name);
  ms::gui::AppOptions options = demo_options("P05", dir + "/results.sqlite");
  options.protocol_path = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/" + name + ".yaml";
  ms::gui::MainWindow w(options);
  ASSERT_TRUE(start_window(w));
  const std::size_t total = w.controller()->session().total();
  DriveLog log;
  ASSERT_TRUE(drive(w, log));
  ms::ResultsStore store(dir + "/results.sqlite", ms::ResultsStore::Mode::read_only);
  EXPECT_EQ(store.count("responses"), static_cast<std::int64_t>(total));
}

INSTANTIATE_TEST_SUITE_P(Replications, ShippedProtocol,
                         ::testing::Values("ab_synthesis_methods", "ren2013_materials", "skandalou2017_changepoint",
                                           "skandalou2017_variation", "sterling2019_handtuning"));
