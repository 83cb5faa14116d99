// The participant's window: start page -> one trial view at a time (with progress and the "resumed"
// notice) -> break pages -> the done page. All state lives in the StudyController; this only switches
// pages on its signals.
#pragma once
#include <QLabel>
#include <QMainWindow>
#include <QProgressBar>
#include <QStackedWidget>

#include <memory>

#include "studyapp/gui/app_options.hpp"
#include "studyapp/gui/start_page.hpp"
#include "studyapp/gui/study_controller.hpp"

namespace ms::gui {

class TrialView;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  // With a protocol in `options`, it is loaded (and rendered) at once; with a participant too, the
  // participant only has to press Start.
  explicit MainWindow(const AppOptions& options, QWidget* parent = nullptr);
  ~MainWindow() override;

  StartPage& start_page() { return *start_page_; }
  StudyController* controller() { return controller_.get(); }
  TrialView* trial_view() { return view_; }
  QWidget* current_page() { return pages_->currentWidget(); }

  void load_protocol(const QString& path);
  void start();

 private:
  void show_trial();
  void show_break();
  void show_done();
  void update_header();
  void open_experimenter_view();

  AppOptions options_;
  std::unique_ptr<StudyController> controller_;
  QStackedWidget* pages_;
  StartPage* start_page_;
  QWidget *session_page_, *break_page_, *done_page_;
  QProgressBar* progress_;
  QLabel *position_, *resumed_, *error_, *done_label_;
  QWidget* view_holder_;
  TrialView* view_ = nullptr;
};

}  // namespace ms::gui
