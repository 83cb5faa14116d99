// The README's picture of a sound-variation trial (Skandalou & Ireland 2017, Exp. 2: two bounce sequences,
// no reference, -3...+3), taken by scripts/screenshots.sh on its screens (1024x600, and 1366x768 at
// 150 %) like the other views, each checked for clipped widgets first; skipped outside that script.
#include <QRadioButton>

#include <cstdlib>

#include "gui_fixture.hpp"
#include "widget_fit.hpp"

using namespace gui_test;

TEST(ReadmePictures, SoundVariationTrial) {
  const char* out = std::getenv("MODALSTUDY_README_SHOTS");
  if (!out || !*out) GTEST_SKIP() << "set MODALSTUDY_README_SHOTS (scripts/screenshots.sh does)";
  ms::gui::AppOptions options = demo_options("P07", fresh_dir("readme-variation") + "/results.sqlite");
  options.protocol_path = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/skandalou2017_variation.yaml";
  ms::gui::MainWindow w(options);
  const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
  w.move(screen.topLeft());
  w.resize(screen.size());
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  ASSERT_TRUE(start_window(w));
  bool shot = false;
  DriveLog log;
  ASSERT_TRUE(drive(w, log, 1000, [&](ms::BlockType type, ms::gui::MainWindow& win) {
    if (type != ms::BlockType::ab || shot) return;
    shot = true;
    QWidget* v = win.trial_view();
    // A participant mid-trial: both sounds heard, "B slightly better" chosen.
    for (const char* name : {"play-0", "play-1"}) QTest::mouseClick(child<QPushButton>(v, name), Qt::LeftButton);
    QTest::mouseClick(child<QRadioButton>(v, "bipolar-1"), Qt::LeftButton);
    QTest::qWait(50);
    for (const std::string& problem : clipped_widgets(win)) ADD_FAILURE() << "ab-variation: " << problem;
    const QImage image = win.grab().toImage().convertToFormat(QImage::Format_RGB888);
    EXPECT_TRUE(image.save(QString(out) + "/ab-variation.png", "PNG", 9));
  }));
  EXPECT_TRUE(shot);
}
