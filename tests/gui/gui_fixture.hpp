// Shared by the GUI suites: the QApplication, output folders in the build tree, and a driver that answers
// whatever the window shows (start page, every trial view, break and done pages) through the real widgets
// with QTest mouse clicks and key presses, as a participant would.
#pragma once
#include <QAbstractButton>
#include <QApplication>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QTest>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "studyapp/gui/main_window.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace gui_test {

inline QApplication& app() {
  static int argc = 1;
  static char name[] = "tests_gui";
  static char* argv[] = {name, nullptr};
  static auto* instance = new QApplication(argc, argv);  // never destroyed: widgets may outlive a test
  return *instance;
}

inline std::string demo_protocol() { return std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/demo.yaml"; }
inline std::string out_dir() { return MODALSTUDY_GUI_OUT; }
inline std::string shared_cache() { return out_dir() + "/cache"; }  // rendered once for every suite

inline std::string fresh_dir(const std::string& name) {
  const std::filesystem::path p = std::filesystem::path(out_dir()) / name;
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p.string();
}

// Runs the event loop until pred() or timeout; true when pred() held.
inline bool wait_until(const std::function<bool()>& pred, int timeout_ms = 30000) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  while (!pred()) {
    if (std::chrono::steady_clock::now() > end) return false;
    QTest::qWait(5);
  }
  return true;
}

template <class T = QWidget>
T* child(QWidget* root, const QString& name) {
  T* w = root ? root->findChild<T*>(name) : nullptr;
  if (!w) ADD_FAILURE() << "no widget named " << name.toStdString();
  return w;
}

template <class T = QWidget>
std::vector<T*> children_with_prefix(QWidget* root, const QString& prefix) {
  std::vector<T*> out;
  for (T* w : root->findChildren<T*>())
    if (w->objectName().startsWith(prefix)) out.push_back(w);
  return out;
}

// A mouse click where a person would click: the middle of a push button, the indicator of a radio button
// (a radio stretched by its layout only reacts over its indicator and text).
inline void press(QAbstractButton* b) {
  if (qobject_cast<QPushButton*>(b)) QTest::mouseClick(b, Qt::LeftButton);
  else QTest::mouseClick(b, Qt::LeftButton, {}, QPoint(6, b->height() / 2));
}

inline void click(QWidget* root, const QString& name) {
  if (auto* b = child<QAbstractButton>(root, name)) press(b);
}

inline ms::gui::AppOptions demo_options(const std::string& participant, const std::string& db) {
  app();  // before any widget
  ms::gui::AppOptions o;
  o.protocol_path = demo_protocol();
  o.participant = participant;
  o.db_path = db;
  o.cache_dir = shared_cache();
  o.audio = "null";
  return o;
}

// Shows the window, waits for the stimuli and presses Start.
inline bool start_window(ms::gui::MainWindow& w) {
  app();
  w.show();
  QApplication::setActiveWindow(&w);
  if (!QTest::qWaitForWindowExposed(&w)) return false;
  auto* start = w.start_page().findChild<QPushButton*>("start");
  if (!wait_until([&] { return start->isEnabled(); }, 300000)) return false;
  QTest::mouseClick(start, Qt::LeftButton);
  return w.trial_view() != nullptr || w.current_page()->findChild<QPushButton*>("close");
}

struct DriveLog {
  std::vector<double> resynth_ms;            // adjust: slider move -> new sound ready
  std::vector<std::string> listen_rule;      // trials whose Next was disabled until every sound was heard
  std::set<ms::BlockType> seen;
  int trials = 0, breaks = 0, staircase_steps = 0, limits_steps = 0, tokens_steps = 0;
  int marks_before_hearing = 0;              // changepoint: marks that worked before their sound was heard
  bool used_keys = false;                    // shortcuts (Enter, 1..n) took effect
};

// Answers one trial shown in `w` through its widgets.
inline void answer_trial(ms::gui::MainWindow& w, DriveLog& log) {
  ms::gui::StudyController& c = *w.controller();
  ms::gui::TrialView* view = w.trial_view();
  const ms::Trial trial = c.session().current();
  const std::size_t index = c.session().current_index();
  log.seen.insert(trial.type);
  ++log.trials;
  auto* next = view->findChild<QPushButton*>("next");
  auto play_all = [&] {
    for (auto* b : children_with_prefix<QPushButton>(view, "play-"))
      if (b->objectName() != "play-sequence") QTest::mouseClick(b, Qt::LeftButton);
  };
  auto moved_on = [&] { return c.session().finished() || c.session().current_index() != index || c.session().at_break(); };
  switch (trial.type) {
    case ms::BlockType::instructions:
      QTest::keyClick(view, Qt::Key_Return);  // Enter = Next
      if (moved_on()) log.used_keys = true;
      else QTest::mouseClick(next, Qt::LeftButton);
      return;
    case ms::BlockType::ab: {
      if (auto bipolar = children_with_prefix<QAbstractButton>(view, "bipolar-1"); !bipolar.empty()) {
        press(bipolar[0]);
      } else {
        QTest::keyClick(view, Qt::Key_1);  // 1 = first choice
        auto* first = children_with_prefix<QAbstractButton>(view, "choice-")[0];
        if (!first->isChecked()) QTest::mouseClick(first, Qt::LeftButton);
      }
      if (!next->isEnabled()) log.listen_rule.push_back("ab");  // answered, but nothing heard yet
      play_all();
      QTest::keyClick(view, Qt::Key_Return);
      if (!moved_on()) QTest::mouseClick(next, Qt::LeftButton);
      return;
    }
    case ms::BlockType::mushra: {
      if (!next->isEnabled()) log.listen_rule.push_back("mushra");
      int k = 0;
      for (auto* s : children_with_prefix<QSlider>(view, "mushra-slider-")) {
        for (int i = 0; i <= k; ++i) QTest::keyClick(s, Qt::Key_PageUp);
        ++k;
      }
      play_all();
      QTest::mouseClick(next, Qt::LeftButton);
      return;
    }
    case ms::BlockType::bs1116: {
      if (!next->isEnabled()) log.listen_rule.push_back("bs1116");
      int k = 0;
      for (auto* s : children_with_prefix<QSlider>(view, "mushra-slider-")) {
        for (int i = 0; i <= k; ++i) QTest::keyClick(s, Qt::Key_PageDown);  // from 5.0 down
        ++k;
      }
      play_all();
      QTest::mouseClick(next, Qt::LeftButton);
      return;
    }
    case ms::BlockType::magnitude: {
      auto* entry = child<QLineEdit>(view, "magnitude");
      QTest::keyClicks(entry, "50");
      if (!next->isEnabled()) log.listen_rule.push_back("magnitude");
      const auto buttons = children_with_prefix<QPushButton>(view, "play-");
      if (buttons.size() == 4) EXPECT_FALSE(buttons[2]->isEnabled()) << "the pair before the reference pair";
      play_all();
      play_all();  // the pair becomes playable after the modulus pair
      QTest::keyClick(entry, Qt::Key_Return);
      if (!moved_on()) QTest::mouseClick(next, Qt::LeftButton);
      return;
    }
    case ms::BlockType::identify:
      QTest::mouseClick(children_with_prefix<QAbstractButton>(view, "choice-")[0], Qt::LeftButton);
      if (!next->isEnabled()) log.listen_rule.push_back("identify");
      play_all();
      QTest::mouseClick(next, Qt::LeftButton);
      return;
    case ms::BlockType::rating: {
      for (auto* r : children_with_prefix<QAbstractButton>(view, "rating-"))
        if (r->objectName().endsWith("-5")) press(r);
      if (!next->isEnabled()) log.listen_rule.push_back("rating");
      play_all();
      QTest::mouseClick(next, Qt::LeftButton);
      return;
    }
    case ms::BlockType::adjust: {
      wait_until([&] { return view->property("renders").toInt() >= 1; });
      if (!next->isEnabled()) log.listen_rule.push_back("adjust");  // the sound is ready but not heard
      auto* slider = children_with_prefix<QSlider>(view, "adjust-")[0];
      for (int move = 0; move < 5; ++move) {
        const int before = view->property("renders").toInt();
        QTest::keyClick(slider, Qt::Key_Right);
        wait_until([&] { return view->property("renders").toInt() > before; });
        log.resynth_ms.push_back(view->property("resynth_ms").toDouble());
      }
      play_all();
      wait_until([&] { return next->isEnabled(); });
      QTest::mouseClick(next, Qt::LeftButton);
      return;
    }
    case ms::BlockType::staircase:
      for (int step = 0; step < 100 && !moved_on(); ++step) {
        auto* play0 = child<QPushButton>(view, "play-0");
        wait_until([&] { return play0->isEnabled(); });
        QTest::mouseClick(children_with_prefix<QAbstractButton>(view, "choice-A")[0], Qt::LeftButton);
        if (step == 0 && !next->isEnabled()) log.listen_rule.push_back("staircase");
        play_all();
        QTest::mouseClick(next, Qt::LeftButton);
        ++log.staircase_steps;
      }
      return;
    case ms::BlockType::limits:
      for (int step = 0; step < 100 && !moved_on(); ++step) {
        auto* play0 = child<QPushButton>(view, "play-0");
        wait_until([&] { return play0->isEnabled(); });
        // "same" twice, then "different": a series of three pairs
        const char* answer = step < 2 ? "choice-same" : "choice-different";
        QTest::mouseClick(children_with_prefix<QAbstractButton>(view, answer)[0], Qt::LeftButton);
        if (step == 0 && !next->isEnabled()) log.listen_rule.push_back("limits");
        play_all();
        QTest::mouseClick(next, Qt::LeftButton);
        ++log.limits_steps;
      }
      return;
    case ms::BlockType::tokens:
      for (int step = 0; step < 1000 && !moved_on(); ++step) {
        auto* play0 = child<QPushButton>(view, "play-0");
        wait_until([&] { return play0->isEnabled() && child<QPushButton>(view, "play-1")->isEnabled(); });
        // "different" first (the compared token becomes the reference), then "same"
        const char* answer = step == 0 ? "choice-different" : "choice-same";
        QTest::mouseClick(children_with_prefix<QAbstractButton>(view, answer)[0], Qt::LeftButton);
        if (step == 0 && !next->isEnabled()) log.listen_rule.push_back("tokens");
        play_all();
        QTest::mouseClick(next, Qt::LeftButton);
        ++log.tokens_steps;
      }
      return;
    case ms::BlockType::changepoint: {
      const auto marks = children_with_prefix<QPushButton>(view, "mark-");
      for (auto* m : marks) log.marks_before_hearing += m->isEnabled();
      if (!next->isEnabled()) log.listen_rule.push_back("changepoint");
      play_all();
      if (marks.size() > 2) QTest::mouseClick(child<QPushButton>(view, "mark-2"), Qt::LeftButton);
      QTest::mouseClick(next, Qt::LeftButton);
      return;
    }
    case ms::BlockType::questionnaire:
      for (auto* e : children_with_prefix<QLineEdit>(view, "question-")) QTest::keyClicks(e, "fine, thanks");
      if (auto options = children_with_prefix<QAbstractButton>(view, "option-"); !options.empty())
        press(options[0]);
      QTest::mouseClick(next, Qt::LeftButton);
      return;
    case ms::BlockType::unknown: return;
  }
}

// Answers trials until the done page (or `max_trials` trials, or a trial of type `stop_before`);
// before(type, window) runs as each trial view (or break page: type unknown) is shown. Returns true when
// the done page was reached.
inline bool drive(ms::gui::MainWindow& w, DriveLog& log, int max_trials = 1000,
                  const std::function<void(ms::BlockType, ms::gui::MainWindow&)>& before = {},
                  ms::BlockType stop_before = ms::BlockType::unknown) {
  for (int guard = 0; guard < 2000; ++guard) {
    QCoreApplication::processEvents();
    QWidget* page = w.current_page();
    if (page->findChild<QPushButton*>("close")) return true;
    if (auto* resume = page->findChild<QPushButton*>("continue")) {
      ++log.breaks;
      if (before) before(ms::BlockType::unknown, w);  // the break page
      QTest::keyClick(page, Qt::Key_Return);          // Enter continues
      if (w.current_page() == page) QTest::mouseClick(resume, Qt::LeftButton);
      else log.used_keys = true;
      continue;
    }
    if (log.trials >= max_trials) return false;
    if (!w.trial_view()) return false;
    if (w.controller()->session().current().type == stop_before) return false;
    if (before) before(w.controller()->session().current().type, w);
    const std::size_t index = w.controller()->session().current_index();
    answer_trial(w, log);
    QCoreApplication::processEvents();
    if (!w.controller()->session().finished() && w.controller()->session().current_index() == index &&
        !w.current_page()->findChild<QPushButton*>("continue")) {
      ADD_FAILURE() << "trial " << index << " (" << ms::to_string(w.controller()->session().current().type)
                    << ") was not answered; error: "
                    << (w.findChild<QLabel*>("error") ? w.findChild<QLabel*>("error")->text().toStdString() : "")
                    << "; hint: "
                    << (w.trial_view() && w.trial_view()->findChild<QLabel*>("hint")
                            ? w.trial_view()->findChild<QLabel*>("hint")->text().toStdString() : "");
      return false;
    }
  }
  return false;
}

}  // namespace gui_test
