// The experimenter view's A/B and magnitude pictures, drawn from a demo database the autopilot filled
// (tests/data/answers_v1): one picture per A/B block (proportions with 95 % intervals) and per magnitude
// block (the MDS map of the normalised ratings), each savable as PNG and SVG like the others.
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QPushButton>

#include <filesystem>
#include <fstream>

#include "gui_fixture.hpp"
#include "studyapp/gui/experimenter_window.hpp"

using namespace gui_test;

TEST(ExperimenterPictures, AbProportionsAndTheMagnitudeMapBesideTheOthers) {
  const std::string dir = fresh_dir("experimenter-pictures");
  const std::string db = dir + "/demo.sqlite";
  std::filesystem::copy_file(std::string(MODALSTUDY_SOURCE_DIR) + "/tests/data/answers_v1/demo-autopilot.sqlite", db);
  app();
  ms::gui::ExperimenterWindow w(QString::fromStdString(db));
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  // ab-train, abx, mushra, magnitude, material (identify), staircase.
  EXPECT_EQ(w.picture_count(), 6);
  QStringList titles;
  for (auto* l : w.findChildren<QLabel*>()) titles << l->text();
  const QString all = titles.join("\n");
  EXPECT_TRUE(all.contains("abx: proportion correct per pair (95 % Clopper-Pearson intervals)")) << all.toStdString();
  EXPECT_TRUE(all.contains("ab-train: proportion different per pair")) << all.toStdString();
  EXPECT_TRUE(all.contains("magnitude: magnitude estimates, classical MDS map (1 listener)")) << all.toStdString();
  QString ab_png, magnitude_png;
  for (auto* save : children_with_prefix<QPushButton>(&w, "savePicture")) {
    const QString png = save->property("png").toString();
    if (png.endsWith("/abx-ab.png")) ab_png = png;
    if (png.endsWith("/magnitude-magnitude.png")) magnitude_png = png;
  }
  ASSERT_FALSE(ab_png.isEmpty());
  ASSERT_FALSE(magnitude_png.isEmpty());
  for (const QString& png : {ab_png, magnitude_png}) {
    const QImage image(png);
    EXPECT_GT(image.width(), 400);
    const QString base = QString::fromStdString(dir) + "/" + QFileInfo(png).completeBaseName();
    ASSERT_TRUE(w.save_picture(png, base + ".svg"));
    ASSERT_TRUE(w.save_picture(png, base + ".png"));
    std::ifstream svg((base + ".svg").toStdString());
    std::string head(200, '\0');
    svg.read(head.data(), 200);
    EXPECT_NE(head.find("<svg"), std::string::npos);
    EXPECT_EQ(QImage(base + ".png").size(), image.size());
  }
}
