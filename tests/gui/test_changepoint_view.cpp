// The change-point view on the shipped Q-sweep protocol (19 sounds per trial): on a 1024x600 screen the
// whole sweep shows without scrolling, a sound's "Changed here" works only once that sound was heard,
// Next waits for every sound, and the marks pressed are the answer stored. The picture is written to
// <build>/gui-tests/changepoint-sweep/sweep.png.
#include <QScrollArea>
#include <QScrollBar>

#include "gui_fixture.hpp"
#include "studyapp/core/results_store.hpp"

using namespace gui_test;

TEST(ChangepointView, ANineteenSoundSweepMarksOnlyHeardSoundsAndStoresTheMarks) {
  const std::string dir = fresh_dir("changepoint-sweep");
  ms::gui::AppOptions o = demo_options("C01", dir + "/results.sqlite");
  o.protocol_path = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/skandalou2017_changepoint.yaml";
  ms::gui::MainWindow w(o);
  w.resize(1024, 570);  // a 1024x600 screen without its title bar
  ASSERT_TRUE(start_window(w));
  QTest::keyClick(w.trial_view(), Qt::Key_Return);  // the instructions
  ASSERT_TRUE(wait_until([&] { return w.trial_view() && w.controller()->session().current().type == ms::BlockType::changepoint; }));
  QWidget* v = w.trial_view();
  const ms::Trial sweep = w.controller()->session().current();
  ASSERT_EQ(sweep.stimuli.size(), 19u);
  QTest::qWait(50);
  EXPECT_FALSE(child<QScrollArea>(v, "trialScroll")->verticalScrollBar()->isVisible()) << "the sweep scrolls";

  auto* next = child<QPushButton>(v, "next");
  auto* mark3 = child<QPushButton>(v, "mark-3");
  EXPECT_FALSE(mark3->isEnabled());
  QTest::mouseClick(mark3, Qt::LeftButton);
  EXPECT_FALSE(mark3->isChecked());  // not heard: nothing happens
  for (int i = 0; i < 19; ++i) {
    QTest::mouseClick(child<QPushButton>(v, QString("play-%1").arg(i)), Qt::LeftButton);
    if (i == 3) {
      EXPECT_TRUE(mark3->isEnabled());
      QTest::mouseClick(mark3, Qt::LeftButton);
    }
    if (i < 18) EXPECT_FALSE(next->isEnabled()) << i;
  }
  QTest::mouseClick(child<QPushButton>(v, "mark-12"), Qt::LeftButton);
  EXPECT_TRUE(mark3->isChecked());
  EXPECT_FALSE(child<QPushButton>(v, "mark-0")->isVisible());  // nothing comes before the first sound
  ASSERT_TRUE(next->isEnabled());
  EXPECT_TRUE(w.grab().save(QString::fromStdString(dir + "/sweep.png")));
  QTest::mouseClick(next, Qt::LeftButton);

  ms::ResultsStore store(dir + "/results.sqlite", ms::ResultsStore::Mode::read_only);
  const auto r = store.response(w.controller()->session().id(), {int(sweep.block), int(sweep.index)});
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(nlohmann::json::parse(r->value_json), nlohmann::json::parse(R"({"marks":[3,12]})"));
  EXPECT_EQ(r->plays, 19);
}
