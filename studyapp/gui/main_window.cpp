// MainWindow: pages of the participant's window, driven by StudyController signals.
#include "studyapp/gui/main_window.hpp"

#include <QShortcut>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QVBoxLayout>

#include <filesystem>

#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/participant_status.hpp"
#include "studyapp/core/store_location.hpp"
#include "studyapp/gui/experimenter_window.hpp"
#include "studyapp/gui/trial_view.hpp"
#include "synthesis/input_error.hpp"

namespace ms::gui {

namespace {

QWidget* message_page(const QString& text, QLabel** label, QPushButton** button, const QString& button_text,
                      const QString& name) {
  auto* page = new QWidget;
  auto* layout = new QVBoxLayout(page);
  layout->addStretch();
  *label = new QLabel(text, page);
  (*label)->setAlignment(Qt::AlignCenter);
  (*label)->setWordWrap(true);
  layout->addWidget(*label);
  *button = new QPushButton(button_text, page);
  (*button)->setObjectName(name);
  (*button)->setDefault(true);
  layout->addWidget(*button, 0, Qt::AlignCenter);
  layout->addStretch();
  for (const auto key : {Qt::Key_Return, Qt::Key_Enter, Qt::Key_Space}) {
    auto* shortcut = new QShortcut(QKeySequence(key), page);
    QObject::connect(shortcut, &QShortcut::activated, *button, &QPushButton::click);
  }
  return page;
}

}  // namespace

MainWindow::MainWindow(const AppOptions& options, QWidget* parent) : QMainWindow(parent), options_(options) {
  setWindowTitle("studyapp — ModalStudy");
  // 900 x 620, or less on a small (or scaled) screen: the pages scroll rather than leave the screen.
  const QRect screen = this->screen() ? this->screen()->availableGeometry() : QRect(0, 0, 1024, 600);
  resize(std::min(900, screen.width()), std::min(620, screen.height() - 40));
  pages_ = new QStackedWidget(this);
  setCentralWidget(pages_);

  start_page_ = new StartPage;
  auto* start_scroll = new QScrollArea;  // a small or scaled screen scrolls the form; Start stays in the page
  start_scroll->setObjectName("startScroll");
  start_scroll->setWidgetResizable(true);
  start_scroll->setFrameShape(QFrame::NoFrame);
  start_scroll->setWidget(start_page_);
  pages_->addWidget(start_scroll);
  connect(start_page_, &StartPage::loadRequested, this, &MainWindow::load_protocol);
  connect(start_page_, &StartPage::startRequested, this, &MainWindow::start);
  connect(start_page_, &StartPage::participantChanged, this, &MainWindow::update_participant_status);
  connect(start_page_, &StartPage::audioDeviceChosen, this, [this](const QString& device) {
    if (controller_ && controller_->problems().empty()) start_page_->set_audio_message(controller_->set_audio_device(device));
  });
  connect(start_page_, &StartPage::calibrateRequested, this, [this] {
    if (controller_ && controller_->problems().empty()) controller_->play_calibration_tone();
  });

  session_page_ = new QWidget;
  auto* session_layout = new QVBoxLayout(session_page_);
  auto* header = new QHBoxLayout;
  position_ = new QLabel(session_page_);
  position_->setObjectName("position");
  progress_ = new QProgressBar(session_page_);
  progress_->setObjectName("progress");
  progress_->setFormat("%v of %m answered");
  progress_->setMaximumWidth(360);
  resumed_ = new QLabel(session_page_);
  resumed_->setObjectName("resumedNotice");
  resumed_->setStyleSheet("color: #1f5f9f");
  resumed_->hide();
  header->addWidget(position_, 1);
  header->addWidget(progress_, 1);
  session_layout->addLayout(header);
  session_layout->addWidget(resumed_);
  view_holder_ = new QWidget(session_page_);
  view_holder_->setLayout(new QVBoxLayout);
  view_holder_->layout()->setContentsMargins(0, 0, 0, 0);
  session_layout->addWidget(view_holder_, 1);
  session_layout->setContentsMargins(8, 6, 8, 4);
  error_ = new QLabel(session_page_);
  error_->setObjectName("error");
  error_->setStyleSheet("color: #b00020");
  error_->setWordWrap(true);
  session_layout->addWidget(error_);
  pages_->addWidget(session_page_);

  QLabel* break_label = nullptr;
  QPushButton* resume = nullptr;
  break_page_ = message_page("<h2>Time for a short break</h2>Continue when you are ready.", &break_label, &resume,
                             "Continue", "continue");
  connect(resume, &QPushButton::clicked, this, [this] { controller_->continue_after_break(); });
  pages_->addWidget(break_page_);
  QPushButton* close = nullptr;
  done_page_ = message_page("", &done_label_, &close, "Close", "close");
  connect(close, &QPushButton::clicked, this, &QWidget::close);
  pages_->addWidget(done_page_);

  QMenu* menu = menuBar()->addMenu("&Study");
  experimenter_action_ = menu->addAction("&Experimenter view…", this, [this] { request_experimenter_view(); });
  experimenter_action_->setObjectName("experimenterAction");
  auto* locked = new QShortcut(QKeySequence("Ctrl+Shift+E"), this);
  connect(locked, &QShortcut::activated, this, [this] { request_experimenter_view(); });
  confirm_ = [this] {
    return QMessageBox::question(this, "Experimenter view",
                                 "A participant's session is running. Open the experimenter view (results of "
                                 "every participant) on this screen?",
                                 QMessageBox::Open | QMessageBox::Cancel, QMessageBox::Cancel) == QMessageBox::Open;
  };
  connect(pages_, &QStackedWidget::currentChanged, this, [this] { update_menu(); });
  menu->addAction("&Quit", QKeySequence::Quit, this, &QWidget::close);

  start_page_->set_audio_choices(QString::fromStdString(options_.audio));
  if (!options_.participant.empty()) start_page_->set_participant(QString::fromStdString(options_.participant));
  if (!options_.protocol_path.empty()) {
    start_page_->set_protocol_path(QString::fromStdString(options_.protocol_path));
    load_protocol(QString::fromStdString(options_.protocol_path));
  }
}

MainWindow::~MainWindow() {
  delete view_;
  view_ = nullptr;
}

void MainWindow::load_protocol(const QString& path) {
  delete view_;
  view_ = nullptr;
  const std::string p = path.toStdString();
  const std::string cache = options_.cache_dir.empty() ? default_cache_dir() : options_.cache_dir;
  controller_ = std::make_unique<StudyController>(p, options_.allow_outside, cache);
  QStringList problems;
  for (const std::string& line : controller_->problems()) problems << QString::fromStdString(line);
  start_page_->show_problems(problems);
  if (!problems.isEmpty()) return;
  const Protocol& protocol = controller_->protocol();
  if (options_.db_path.empty() || start_page_->db_path().isEmpty())
    start_page_->set_db_path(QString::fromStdString(
        options_.db_path.empty() ? default_db_path(p, protocol.study) : options_.db_path));
  start_page_->show_loaded(QString::fromStdString(protocol.title.empty() ? protocol.study : protocol.title),
                           static_cast<int>(protocol.stimuli.size()));
  StudyController* c = controller_.get();
  connect(c, &StudyController::prepareProgress, start_page_, &StartPage::show_progress);
  connect(c, &StudyController::prepared, start_page_, &StartPage::show_prepared);
  connect(c, &StudyController::trialShown, this, &MainWindow::show_trial);
  connect(c, &StudyController::breakReached, this, &MainWindow::show_break);
  connect(c, &StudyController::finished, this, &MainWindow::show_done);
  connect(c, &StudyController::error, error_, &QLabel::setText);
  const QString audio_message = c->set_audio_device(start_page_->audio_device());
  if (!audio_message.isEmpty()) start_page_->set_audio_message(audio_message);
  c->prepare();
  update_participant_status();
}

void MainWindow::update_participant_status() {
  if (!controller_ || !controller_->problems().empty() || start_page_->participant().isEmpty() ||
      start_page_->db_path().isEmpty())
    return start_page_->show_participant_status(QString(), false, {});
  try {
    const ParticipantStatus status = participant_status(start_page_->db_path().toStdString(),
                                                        controller_->protocol().study,
                                                        start_page_->participant().toStdString());
    QString line = QString::fromStdString(describe(status));
    if (status.state == ParticipantStatus::State::unfinished) line += "; Start resumes it.";
    else if (status.state == ParticipantStatus::State::finished) line += ".";
    if (status.autopilot && status.state != ParticipantStatus::State::none) line += " (simulated by the autopilot)";
    QStringList look_alikes;
    for (const std::string& id : status.look_alikes) look_alikes << QString::fromStdString(id);
    start_page_->show_participant_status(line, status.state == ParticipantStatus::State::finished, look_alikes);
  } catch (const std::exception& e) {
    start_page_->show_participant_status(QString::fromStdString(e.what()), false, {});
  }
}

void MainWindow::start() {
  if (!controller_ || !controller_->is_prepared()) return;
  const std::filesystem::path db = start_page_->db_path().toStdString();
  std::error_code ignored;  // an unusable folder is reported by the store, naming the file
  if (db.has_parent_path() && !is_postgres_uri(db.string())) std::filesystem::create_directories(db.parent_path(), ignored);
  try {
    SessionStart how;
    how.new_session = start_page_->new_session() || options_.new_session;
    controller_->start_session(start_page_->participant().toStdString(), start_page_->db_path().toStdString(), how);
  } catch (const std::exception& e) {
    QMessageBox::warning(this, "Cannot start the session", QString::fromStdString(e.what()));
    return;
  }
  Session& s = controller_->session();
  resumed_at_ = s.answered();
  if (s.resumed() && !s.finished()) {
    resumed_->setText(QString("Resumed an unfinished session: continuing at trial %1 of %2 (earlier answers are kept).")
                          .arg(s.answered() + 1)
                          .arg(s.total()));
    resumed_->show();
  }
}

void MainWindow::preview(const Trial& trial) {
  if (!controller_ || !controller_->problems().empty()) return;
  controller_->preview(trial);
  show_trial();
}

void MainWindow::show_trial() {
  if (view_) {
    view_->hide();
    view_->deleteLater();  // may be inside its own Next handler
  }
  error_->clear();
  if (controller_->previewing() || controller_->session().answered() > resumed_at_)
    resumed_->hide();  // said once, on the first trial
  view_ = make_trial_view(*controller_, view_holder_);
  view_holder_->layout()->addWidget(view_);
  view_->show();
  pages_->setCurrentWidget(session_page_);
  update_header();
  view_->setFocus();
}

void MainWindow::show_break() {
  if (view_) {
    view_->hide();
    view_->deleteLater();
    view_ = nullptr;
  }
  pages_->setCurrentWidget(break_page_);
}

void MainWindow::show_done() {
  if (view_) {
    view_->hide();
    view_->deleteLater();
    view_ = nullptr;
  }
  Session& s = controller_->session();
  done_label_->setText(QString("<h2>Thank you!</h2>All %1 trials are answered and saved.<br>Results: %2")
                           .arg(s.total())
                           .arg(QString::fromStdString(s.store().path())));
  pages_->setCurrentWidget(done_page_);
}

void MainWindow::update_header() {
  const bool live = !controller_->previewing();
  const std::size_t total = live ? controller_->session().total() : 1;
  const std::size_t answered = live ? controller_->session().answered() : 0;
  const std::size_t index = live ? controller_->session().current_index() : 0;
  progress_->setRange(0, static_cast<int>(total));
  progress_->setValue(static_cast<int>(answered));
  const Trial& t = controller_->trial();
  position_->setText(QString("%1<b>%2</b> \u00B7 trial %3 of %4")
                         .arg(t.training ? QString("Practice \u00B7 ") : QString())
                         .arg(task_title(controller_->block()))
                         .arg(index + 1)
                         .arg(total));
}

bool MainWindow::in_session() const {
  const QWidget* page = pages_->currentWidget();
  return page == session_page_ || page == break_page_;
}

void MainWindow::update_menu() {
  if (!experimenter_action_) return;
  experimenter_action_->setEnabled(!in_session());
  experimenter_action_->setText(in_session() ? "&Experimenter view… (Ctrl+Shift+E)" : "&Experimenter view…");
}

QWidget* MainWindow::request_experimenter_view() {
  if (in_session() && !(confirm_ && confirm_())) return nullptr;
  return open_experimenter_view();
}

QWidget* MainWindow::open_experimenter_view() {
  const QString db = controller_ && controller_->problems().empty() ? start_page_->db_path() : QString();
  auto* w = new ExperimenterWindow(db);
  w->setAttribute(Qt::WA_DeleteOnClose);
  w->show();
  return w;
}

}  // namespace ms::gui
