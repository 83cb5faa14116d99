// The README's pictures of every view (scripts/screenshots.sh runs this under Xvfb; skipped otherwise):
// a demo session driven through the views on a screen of MODALSTUDY_SCREEN (e.g. 1024x600), one PNG per
// view into MODALSTUDY_README_SHOTS, each checked for clipped widgets first; then the experimenter view
// over that session and three simulated ones.
#include <QProcess>
#include <QScreen>

#include <cstdlib>
#include <map>

#include "gui_fixture.hpp"
#include "studyapp/gui/experimenter_window.hpp"
#include "widget_fit.hpp"

using namespace gui_test;

namespace {

void shoot(QWidget& window, const std::string& dir, const std::string& name) {
  QTest::qWait(50);
  for (const std::string& problem : clipped_widgets(window)) ADD_FAILURE() << name << ": " << problem;
  const QImage image = window.grab().toImage().convertToFormat(QImage::Format_RGB888);
  EXPECT_TRUE(image.save(QString::fromStdString(dir + "/" + name + ".png"), "PNG", 9)) << name;
}

}  // namespace

TEST(ReadmePictures, EveryViewOnTheGivenScreen) {
  const char* out = std::getenv("MODALSTUDY_README_SHOTS");
  if (!out || !*out) GTEST_SKIP() << "set MODALSTUDY_README_SHOTS (scripts/screenshots.sh does)";
  const std::string dir = out;
  std::filesystem::create_directories(dir);
  const std::string db = fresh_dir("readme-db") + "/results.sqlite";
  for (const char* p : {"S01", "S02", "S03"}) {  // simulated participants for the experimenter's pictures
    QProcess pilot;
    pilot.start(STUDYAPP_BIN, {QString::fromStdString(demo_protocol()), "--participant", p, "--db",
                               QString::fromStdString(db), "--autopilot", "7", "--cache", QString::fromStdString(shared_cache())});
    ASSERT_TRUE(pilot.waitForFinished(300000));
    ASSERT_EQ(pilot.exitCode(), 0) << pilot.readAllStandardError().toStdString();
  }
  ms::gui::MainWindow w(demo_options("P07", db));
  const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
  w.move(screen.topLeft());
  w.resize(screen.size());
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  ASSERT_TRUE(wait_until([&] { return w.start_page().findChild<QPushButton*>("start")->isEnabled(); }, 300000));
  shoot(w, dir, "start");
  ASSERT_TRUE(start_window(w));
  std::map<ms::BlockType, bool> shot;
  DriveLog log;
  ASSERT_TRUE(drive(w, log, 1000, [&](ms::BlockType type, ms::gui::MainWindow& win) {
    if (type == ms::BlockType::unknown || shot[type]) return;
    shot[type] = true;
    QWidget* v = win.trial_view();
    // A participant mid-trial: the first sounds heard, so the marks and hints show.
    const bool rendered_live = type == ms::BlockType::adjust || type == ms::BlockType::staircase ||
                               type == ms::BlockType::limits || type == ms::BlockType::tokens;
    if (auto* p = v->findChild<QPushButton*>("play-0"); p && !rendered_live) QTest::mouseClick(p, Qt::LeftButton);
    if (type == ms::BlockType::changepoint) {  // three sounds heard, a change marked at the third
      for (const char* name : {"play-1", "play-2"}) QTest::mouseClick(child<QPushButton>(v, name), Qt::LeftButton);
      QTest::mouseClick(child<QPushButton>(v, "mark-2"), Qt::LeftButton);
    }
    if (rendered_live) wait_until([&] { auto* p = v->findChild<QPushButton*>("play-0"); return p && p->isEnabled(); });
    shoot(win, dir, ms::to_string(type));
  }));
  EXPECT_EQ(shot.size(), ms::block_type_names().size());
  ms::gui::ExperimenterWindow experimenter(QString::fromStdString(db));
  experimenter.move(screen.topLeft());
  experimenter.resize(screen.size());
  experimenter.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&experimenter));
  shoot(experimenter, dir, "experimenter");
  auto* tabs = experimenter.findChild<QTabWidget*>();
  ASSERT_NE(tabs, nullptr);
  tabs->setCurrentIndex(1);  // the analysis pictures
  QTest::qWait(50);
  shoot(experimenter, dir, "experimenter-pictures");
}
