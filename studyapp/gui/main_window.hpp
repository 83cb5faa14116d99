// The participant's window: start page -> one trial view at a time (with progress and, on the first
// trial of a resumed session, the "resumed" notice) -> break pages -> the done page. All state lives in
// the StudyController; this only switches pages on its signals. The experimenter view opens from the
// menu on the start and done pages; during a session only with Ctrl+Shift+E and a confirmation, so a
// participant cannot wander into other people's results.
#pragma once
#include <QLabel>
#include <QMainWindow>
#include <QProgressBar>
#include <QStackedWidget>

#include <functional>
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
  // Shows the view of `trial` without a session (layout checks, pictures of every block type).
  void preview(const Trial& trial);

  // Opens the experimenter view if allowed now (asking first during a session); the opened window or null.
  QWidget* request_experimenter_view();
  // Replaces the confirmation dialog (tests): returns whether the experimenter confirmed.
  void set_experimenter_confirmation(std::function<bool()> confirm) { confirm_ = std::move(confirm); }
  bool in_session() const;

 private:
  void show_trial();
  void show_break();
  void show_done();
  void update_header();
  QWidget* open_experimenter_view();
  void update_menu();
  void update_participant_status();

  AppOptions options_;
  std::unique_ptr<StudyController> controller_;
  QStackedWidget* pages_;
  StartPage* start_page_;
  QWidget *session_page_, *break_page_, *done_page_;
  QProgressBar* progress_;
  QLabel *position_, *resumed_, *error_, *done_label_;
  QWidget* view_holder_;
  TrialView* view_ = nullptr;
  class QAction* experimenter_action_ = nullptr;
  std::function<bool()> confirm_;
  std::size_t resumed_at_ = 0;  // answered trials when the session was resumed
};

}  // namespace ms::gui
