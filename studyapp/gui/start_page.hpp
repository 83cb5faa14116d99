// The start page: choose the protocol (its problems listed, every one), the participant and the results
// file; choose and check the audio device (1 kHz calibration tone); watch the stimuli render; start.
#pragma once
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QWidget>

namespace ms::gui {

class StartPage : public QWidget {
  Q_OBJECT

 public:
  explicit StartPage(QWidget* parent = nullptr);

  QString protocol_path() const { return protocol_->text().trimmed(); }
  QString participant() const { return participant_->text().trimmed(); }
  QString db_path() const { return db_->text().trimmed(); }
  QString audio_device() const;  // "default", "null" or a description

  void set_protocol_path(const QString& path) { protocol_->setText(path); }
  void set_participant(const QString& id) { participant_->setText(id); }
  void set_db_path(const QString& path) { db_->setText(path); }
  // Fills the device list (default, each system output, null) and selects `device` when present.
  void set_audio_choices(const QString& device);
  void set_audio_message(const QString& message);

  void show_problems(const QStringList& problems);      // empty: hides the list
  void show_loaded(const QString& title, int stimuli);  // a valid protocol is loaded
  void show_progress(int done, int total, const QString& name);
  void show_prepared(const QString& error);
  // What the results file holds for the typed participant: one line (finished / unfinished / nothing),
  // look-alike ids; a finished participant starts only with "Run a new session" checked.
  void show_participant_status(const QString& line, bool finished, const QStringList& look_alikes);
  bool new_session() const { return new_session_->isChecked(); }

 signals:
  void loadRequested(QString path);
  void audioDeviceChosen(QString device);
  void calibrateRequested();
  void startRequested();
  void participantChanged();  // the participant or the results file was edited

 private:
  void update_start();

  QLineEdit *protocol_, *participant_, *db_;
  QPlainTextEdit* problems_;
  QLabel *title_, *audio_message_, *progress_label_, *status_;
  QCheckBox* new_session_;
  bool finished_ = false;
  QComboBox* audio_;
  QPushButton *calibrate_, *start_;
  QProgressBar* progress_;
  bool prepared_ = false;
};

}  // namespace ms::gui
