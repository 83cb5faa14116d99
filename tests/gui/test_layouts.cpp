// Layouts of every block of every shipped protocol (and an 11-stimulus MUSHRA trial): the window fits a
// 1024x600 screen at 100 % and a 1366x768 screen at QT_SCALE_FACTOR=1.5 (910x512 logical pixels; the
// factor scales fonts and widgets alike, so logical sizes are those at 100 %), minus a 30 px title bar.
// At those sizes no interactive widget is clipped (the trial body may scroll vertically, never
// sideways; Next stays in the window), and on a 1920x1080 screen lines stay readable and the rating
// scale's end labels stay beside it.
#include <QLabel>
#include <QRadioButton>
#include <QScrollArea>
#include <QScrollBar>

#include <fstream>

#include "gui_fixture.hpp"
#include "studyapp/core/schedule.hpp"
#include "widget_fit.hpp"

using namespace gui_test;

namespace {

struct Screen {
  const char* name;
  int width, height;  // logical pixels available to the window (title bar taken off)
};
constexpr Screen kSmall{"1024x600 at 100 %", 1024, 570};
constexpr Screen kScaled{"1366x768 at 150 %", 910, 482};

std::string eleven_mushra_protocol() {
  const std::string dir = fresh_dir("layout-mushra11");
  const std::string st = std::string(MODALSTUDY_SOURCE_DIR) + "/stimuli/";
  std::ofstream out(dir + "/p.yaml");
  out << "study: m11\nstimuli:\n  ref: {paramset: " << st << "bar/sterling-steel.yaml}\n";
  std::string conditions;
  for (int i = 1; i <= 8; ++i) {
    out << "  c" << i << ": {paramset: " << st << "bar/sterling-steel.yaml, set: {duration_s: " << 0.2 + 0.1 * i << "}}\n";
    conditions += (i > 1 ? ", c" : "c") + std::to_string(i);
  }
  out << "blocks:\n  - {type: mushra, reference: ref, conditions: [" << conditions << "], anchors: auto}\n";
  return dir + "/p.yaml";
}

void check_block_layouts(const std::string& protocol) {
  ms::gui::AppOptions o = demo_options("layout", fresh_dir("layout-db") + "/r.sqlite");
  o.protocol_path = protocol;
  o.allow_outside = true;
  ms::gui::MainWindow w(o);
  ASSERT_NE(w.controller(), nullptr);
  ASSERT_TRUE(w.controller()->problems().empty()) << w.controller()->problems()[0];
  w.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&w));
  const ms::Schedule schedule = ms::make_schedule(w.controller()->protocol(), "layout");
  std::set<std::size_t> seen;
  for (const ms::Trial& t : schedule.trials) {
    if (!seen.insert(t.block).second) continue;
    w.preview(t);
    const std::string what = protocol.substr(protocol.rfind('/') + 1) + " block " + t.block_id;
    for (const Screen& s : {kSmall, kScaled}) {
      const QSize min = w.minimumSizeHint().expandedTo(w.minimumSize());
      EXPECT_LE(min.width(), s.width) << what << " on " << s.name;
      EXPECT_LE(min.height(), s.height) << what << " on " << s.name;
      w.resize(s.width, s.height);
      QTest::qWait(20);
      for (const std::string& problem : clipped_widgets(w)) ADD_FAILURE() << what << " on " << s.name << ": " << problem;
      auto* scroll = w.trial_view()->findChild<QScrollArea*>("trialScroll");
      ASSERT_NE(scroll, nullptr);
      EXPECT_FALSE(scroll->horizontalScrollBar()->isVisible()) << what << " scrolls sideways on " << s.name;
    }
    // A wide screen: readable lines, end labels beside their scale.
    w.resize(1920, 1050);
    QTest::qWait(20);
    for (auto* prompt : w.trial_view()->findChildren<QLabel*>("prompt"))
      EXPECT_LE(prompt->width(), prompt->fontMetrics().averageCharWidth() * 85) << what << ": prompt too wide";
    if (t.type == ms::BlockType::rating) {
      const auto points = children_with_prefix<QRadioButton>(w.trial_view(), "rating-");
      ASSERT_FALSE(points.empty());
      const int scale_right = points.back()->mapTo(&w, QPoint(points.back()->width(), 0)).x();
      int nearest = 1 << 20;
      for (auto* l : w.trial_view()->findChildren<QLabel*>()) {
        const int left = l->mapTo(&w, QPoint(0, 0)).x();
        if (left >= scale_right && !l->text().isEmpty()) nearest = std::min(nearest, left - scale_right);
      }
      EXPECT_LE(nearest, 40) << what << ": the high end label drifted " << nearest << " px from the scale";
    }
  }
  EXPECT_EQ(seen.size(), w.controller()->protocol().blocks.size());
  // The start page fits too (it scrolls; Start stays reachable).
  ms::gui::MainWindow fresh(o);
  fresh.show();
  for (const Screen& s : {kSmall, kScaled}) {
    const QSize min = fresh.minimumSizeHint().expandedTo(fresh.minimumSize());
    EXPECT_LE(min.height(), s.height) << "start page on " << s.name;
    EXPECT_LE(min.width(), s.width) << "start page on " << s.name;
  }
}

}  // namespace

class Layout : public ::testing::TestWithParam<const char*> {};

TEST_P(Layout, EveryBlockFitsSmallAndScaledScreens) {
  const std::string name = GetParam();
  check_block_layouts(name == std::string("mushra11") ? eleven_mushra_protocol()
                                                      : std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/" + name + ".yaml");
}

INSTANTIATE_TEST_SUITE_P(Shipped, Layout,
                         ::testing::Values("demo", "ab_synthesis_methods", "ren2013_materials", "sterling2019",
                                           "sterling2019_handtuning", "vandendoel2002", "skandalou2017_changepoint",
                                           "skandalou2017_variation", "mushra11"));
