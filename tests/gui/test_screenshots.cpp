// Every page of the window and the experimenter view, grabbed (QWidget::grab) during a demo session:
// each picture must be non-blank (pixel variance) and hold the widgets its view is made of. The PNGs are
// written to <build>/gui-tests/screenshots[-TAG]/ (CTest also runs this under xvfb-run, TAG=xvfb).
#include <QImage>
#include <QLabel>
#include <QRadioButton>

#include <cstdlib>
#include <fstream>
#include <map>

#include "gui_fixture.hpp"
#include "studyapp/gui/experimenter_window.hpp"

using namespace gui_test;

namespace {

// Variance of the grey level over all pixels (0 for a blank picture).
double grey_variance(const QImage& image) {
  const QImage g = image.convertToFormat(QImage::Format_Grayscale8);
  double sum = 0, sum2 = 0;
  const double n = static_cast<double>(g.width()) * g.height();
  for (int y = 0; y < g.height(); ++y) {
    const uchar* row = g.constScanLine(y);
    for (int x = 0; x < g.width(); ++x) {
      sum += row[x];
      sum2 += static_cast<double>(row[x]) * row[x];
    }
  }
  const double mean = sum / n;
  return sum2 / n - mean * mean;
}

std::string shots_dir() {
  const char* tag = std::getenv("MODALSTUDY_SHOTS_TAG");
  static const std::string dir = fresh_dir(tag && *tag ? std::string("screenshots-") + tag : "screenshots");
  return dir;
}

void check_picture(QWidget& widget, const std::string& name) {
  const QImage image = widget.grab().toImage();
  ASSERT_FALSE(image.isNull()) << name;
  EXPECT_GT(grey_variance(image), 50.0) << name << " looks blank";
  EXPECT_TRUE(image.save(QString::fromStdString(shots_dir() + "/" + name + ".png"))) << name;
}

std::size_t count_prefix(QWidget* root, const QString& prefix) {
  return children_with_prefix<QWidget>(root, prefix).size();
}

void check_widgets(ms::BlockType type, ms::gui::MainWindow& w) {
  QWidget* v = w.trial_view();
  const ms::Trial& t = w.controller()->session().current();
  EXPECT_NE(v->findChild<QPushButton*>("next"), nullptr);
  EXPECT_NE(w.findChild<QProgressBar*>("progress"), nullptr);
  switch (type) {
    case ms::BlockType::instructions: EXPECT_NE(v->findChild<QLabel*>("instructions"), nullptr); break;
    case ms::BlockType::ab:
      EXPECT_EQ(count_prefix(v, "play-"), t.stimuli.size());
      EXPECT_GE(count_prefix(v, "choice-") + count_prefix(v, "bipolar-"), 2u);
      break;
    case ms::BlockType::mushra:
      EXPECT_EQ(count_prefix(v, "quality-"), 5u);  // Excellent, Good, Fair, Poor, Bad
      EXPECT_EQ(count_prefix(v, "mushra-slider-"), t.stimuli.size());
      EXPECT_EQ(count_prefix(v, "play-"), t.stimuli.size() + 1);  // + the open reference
      EXPECT_NE(v->findChild<QWidget*>("loop"), nullptr);
      break;
    case ms::BlockType::bs1116:
      EXPECT_EQ(count_prefix(v, "quality-"), 5u);  // the five impairment grades
      EXPECT_EQ(count_prefix(v, "mushra-slider-"), 2u);  // A and B, one the hidden reference
      EXPECT_EQ(count_prefix(v, "play-"), 3u);
      break;
    case ms::BlockType::magnitude:
      EXPECT_NE(v->findChild<QLineEdit*>("magnitude"), nullptr);
      EXPECT_EQ(count_prefix(v, "play-"), 4u);  // modulus pair + the pair
      break;
    case ms::BlockType::identify: EXPECT_EQ(count_prefix(v, "choice-"), 3u); break;  // metal, glass, wood
    case ms::BlockType::rating: EXPECT_EQ(count_prefix(v, "rating-brightness-"), 7u); break;
    case ms::BlockType::adjust: EXPECT_EQ(children_with_prefix<QSlider>(v, "adjust-").size(), 1u); break;
    case ms::BlockType::staircase:
      EXPECT_NE(v->findChild<QPushButton*>("play-sequence"), nullptr);
      EXPECT_EQ(count_prefix(v, "choice-"), 2u);
      break;
    case ms::BlockType::limits:
      EXPECT_NE(v->findChild<QPushButton*>("play-sequence"), nullptr);
      EXPECT_EQ(count_prefix(v, "choice-"), 2u);  // same, different
      EXPECT_EQ(count_prefix(v, "play-"), 3u);    // the sequence, the reference, the second sound
      break;
    case ms::BlockType::tokens:
      EXPECT_NE(v->findChild<QPushButton*>("play-sequence"), nullptr);
      EXPECT_EQ(count_prefix(v, "choice-"), 2u);  // same, different
      EXPECT_EQ(count_prefix(v, "play-"), 3u);    // the sequence, the reference token, the next token
      break;
    case ms::BlockType::changepoint:
      EXPECT_EQ(count_prefix(v, "play-"), t.stimuli.size() + 1);  // one per sound of the sweep + the sequence
      EXPECT_EQ(count_prefix(v, "mark-"), t.stimuli.size());      // the first is a placeholder, never enabled
      break;
    case ms::BlockType::questionnaire:
      EXPECT_EQ(count_prefix(v, "question-"), 1u);
      EXPECT_EQ(count_prefix(v, "option-headphones-"), 3u);
      break;
    case ms::BlockType::unknown: break;
  }
}

}  // namespace

TEST(Screenshots, EveryViewRendersWithItsWidgets) {
  const std::string dir = fresh_dir(std::string("shots-db") + (std::getenv("MODALSTUDY_SHOTS_TAG") ? "-tag" : ""));
  const std::string db = dir + "/results.sqlite";
  ms::gui::MainWindow w(demo_options("S01", db));
  app();
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  ASSERT_TRUE(wait_until([&] { return w.start_page().findChild<QPushButton*>("start")->isEnabled(); }, 300000));
  check_picture(w, "start");

  ASSERT_TRUE(start_window(w));
  std::map<ms::BlockType, bool> shot;
  bool break_shot = false;
  DriveLog log;
  ASSERT_TRUE(drive(w, log, 1000, [&](ms::BlockType type, ms::gui::MainWindow& win) {
    if (type == ms::BlockType::unknown) {
      if (!break_shot) check_picture(win, "break");
      break_shot = true;
      return;
    }
    if (shot[type]) return;
    shot[type] = true;
    if (type == ms::BlockType::adjust || type == ms::BlockType::staircase || type == ms::BlockType::limits ||
        type == ms::BlockType::tokens)  // the first render
      wait_until([&] {
        auto* p = win.trial_view()->findChild<QPushButton*>("play-0");
        return type == ms::BlockType::adjust ? win.trial_view()->property("renders").toInt() >= 1 : p && p->isEnabled();
      });
    check_widgets(type, win);
    check_picture(win, ms::to_string(type));
  }));
  EXPECT_EQ(shot.size(), ms::block_type_names().size());
  EXPECT_TRUE(break_shot);
  check_picture(w, "done");

  ms::gui::ExperimenterWindow experimenter(QString::fromStdString(db));
  experimenter.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&experimenter));
  EXPECT_EQ(experimenter.sessions().rowCount(), 1);
  EXPECT_EQ(experimenter.picture_count(), 6);  // A/B x2, MUSHRA boxes, magnitude map, identify confusion, staircase tracks
  EXPECT_EQ(experimenter.sessions().item(0, 7)->text(), "participant");  // not simulated
  {
    const auto saves = children_with_prefix<QPushButton>(&experimenter, "savePicture");
    ASSERT_EQ(saves.size(), 6u);
    const QString png = saves[0]->property("png").toString();
    EXPECT_TRUE(experimenter.save_picture(png, QString::fromStdString(dir + "/picture.svg")));
    EXPECT_TRUE(experimenter.save_picture(png, QString::fromStdString(dir + "/picture.png")));
    EXPECT_FALSE(experimenter.save_picture(png, QString::fromStdString(dir + "/picture.jpg")));
    std::ifstream svg(dir + "/picture.svg");
    std::string head(200, '\0');
    svg.read(head.data(), 200);
    EXPECT_NE(head.find("<svg"), std::string::npos) << head;
    EXPECT_GT(std::filesystem::file_size(dir + "/picture.png"), 1000u);
    EXPECT_FALSE(std::filesystem::exists(dir + "/picture.jpg"));
  }
  bool post_screened = false;
  for (auto* l : experimenter.findChildren<QLabel*>()) post_screened = post_screened || l->text().contains("kept by post-screening");
  EXPECT_TRUE(post_screened);
  check_picture(experimenter, "experimenter");
  ASSERT_TRUE(experimenter.export_to(QString::fromStdString(dir + "/export")));
  EXPECT_TRUE(std::filesystem::exists(dir + "/export/responses.csv"));
}
