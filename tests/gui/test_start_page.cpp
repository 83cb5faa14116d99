// The start page without a protocol on the command line: a malformed protocol typed in shows every
// problem and keeps Start disabled; a good one renders with progress and enables Start once a
// participant is given.
#include <QPlainTextEdit>
#include <QProgressBar>

#include <fstream>

#include "gui_fixture.hpp"

using namespace gui_test;

TEST(StartPage, ShowsEveryProblemOfAProtocolAndStartsOnlyWhenReady) {
  app();
  const std::string dir = fresh_dir("start-page");
  const std::string bad = dir + "/bad.yaml";
  std::ofstream(bad) << "study: bad\nsample_rate: 44100\nseed: 1\nstimuli:\n  a: {paramset: nowhere.yaml}\n"
                        "blocks:\n  - {type: idntify, stimuli: [a], labels: [x]}\n  - {type: ab, pairs: [[a, zz]]}\n";
  ms::gui::AppOptions options;
  options.db_path = dir + "/r.sqlite";
  options.cache_dir = shared_cache();
  options.audio = "null";
  ms::gui::MainWindow w(options);
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  auto* path = child<QLineEdit>(&w, "protocolPath");
  auto* start = child<QPushButton>(&w, "start");
  auto* problems = child<QPlainTextEdit>(&w, "problems");
  ASSERT_TRUE(path && start && problems);

  QTest::keyClicks(path, QString::fromStdString(bad));
  click(&w, "load");
  EXPECT_TRUE(problems->isVisible());
  EXPECT_GE(problems->toPlainText().split('\n').size(), 3) << problems->toPlainText().toStdString();
  EXPECT_FALSE(start->isEnabled());

  path->clear();
  QTest::keyClicks(path, QString::fromStdString(demo_protocol()));
  QTest::keyClick(path, Qt::Key_Return);
  EXPECT_FALSE(problems->isVisible());
  auto* progress = child<QProgressBar>(&w, "prepareProgress");
  ASSERT_TRUE(wait_until([&] { return progress->value() == progress->maximum(); }, 300000));
  EXPECT_TRUE(wait_until([&] { return w.controller()->is_prepared(); }));
  EXPECT_FALSE(start->isEnabled()) << "no participant yet";
  QTest::keyClicks(child<QLineEdit>(&w, "participant"), "P11");
  EXPECT_TRUE(start->isEnabled());
  QTest::mouseClick(start, Qt::LeftButton);
  ASSERT_NE(w.trial_view(), nullptr);
  EXPECT_EQ(w.controller()->session().total(), w.controller()->session().schedule().trials.size());
}
