// StartPage: the form before a session; MainWindow connects its signals to the StudyController.
#include "studyapp/gui/start_page.hpp"

#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QVBoxLayout>

#include "studyapp/gui/audio_output.hpp"

namespace ms::gui {

StartPage::StartPage(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  auto* heading = new QLabel("<h2>ModalStudy — listening test</h2>", this);
  layout->addWidget(heading);
  auto* form = new QFormLayout;

  protocol_ = new QLineEdit(this);
  protocol_->setObjectName("protocolPath");
  auto* browse = new QPushButton("Browse…", this);
  auto* load = new QPushButton("Load", this);
  load->setObjectName("load");
  auto* protocol_row = new QHBoxLayout;
  protocol_row->addWidget(protocol_, 1);
  protocol_row->addWidget(browse);
  protocol_row->addWidget(load);
  form->addRow("Protocol", protocol_row);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, "Protocol", QString(), "Protocols (*.yaml *.yml)");
    if (path.isEmpty()) return;
    protocol_->setText(path);
    emit loadRequested(path);
  });
  connect(load, &QPushButton::clicked, this, [this] { emit loadRequested(protocol_path()); });
  connect(protocol_, &QLineEdit::returnPressed, this, [this] { emit loadRequested(protocol_path()); });

  title_ = new QLabel("(no protocol loaded)", this);
  title_->setObjectName("studyTitle");
  form->addRow("Study", title_);
  participant_ = new QLineEdit(this);
  participant_->setObjectName("participant");
  participant_->setPlaceholderText("e.g. P07");
  connect(participant_, &QLineEdit::textChanged, this, [this] {
    update_start();
    emit participantChanged();
  });
  form->addRow("Participant", participant_);
  status_ = new QLabel(this);
  status_->setObjectName("participantStatus");
  status_->setWordWrap(true);
  status_->setStyleSheet("color: #1f5f9f");
  new_session_ = new QCheckBox("Run a new session for this participant", this);
  new_session_->setObjectName("newSession");
  new_session_->hide();
  connect(new_session_, &QCheckBox::toggled, this, [this] { update_start(); });
  auto* status_box = new QVBoxLayout;
  status_box->addWidget(status_);
  status_box->addWidget(new_session_);
  form->addRow(QString(), status_box);
  db_ = new QLineEdit(this);
  db_->setObjectName("db");
  connect(db_, &QLineEdit::textChanged, this, [this] { emit participantChanged(); });
  form->addRow("Results file", db_);

  audio_ = new QComboBox(this);
  audio_->setObjectName("audioDevice");
  calibrate_ = new QPushButton("Calibration tone (1 kHz, −20 dBFS)", this);
  calibrate_->setObjectName("calibrate");
  calibrate_->setEnabled(false);
  auto* audio_row = new QHBoxLayout;
  audio_row->addWidget(audio_, 1);
  audio_row->addWidget(calibrate_);
  form->addRow("Audio output", audio_row);
  audio_message_ = new QLabel(this);
  audio_message_->setObjectName("audioMessage");
  audio_message_->setWordWrap(true);
  audio_message_->setStyleSheet("color: #a04000");
  form->addRow(QString(), audio_message_);
  connect(audio_, &QComboBox::activated, this, [this] { emit audioDeviceChosen(audio_device()); });
  connect(calibrate_, &QPushButton::clicked, this, [this] { emit calibrateRequested(); });

  progress_ = new QProgressBar(this);
  progress_->setObjectName("prepareProgress");
  progress_->setRange(0, 1);
  progress_->setValue(0);
  progress_label_ = new QLabel(this);
  progress_label_->setObjectName("prepareLabel");
  form->addRow("Stimuli", progress_);
  form->addRow(QString(), progress_label_);
  layout->addLayout(form);

  problems_ = new QPlainTextEdit(this);
  problems_->setObjectName("problems");
  problems_->setReadOnly(true);
  problems_->hide();
  layout->addWidget(problems_);
  layout->addStretch();

  start_ = new QPushButton("Start", this);
  start_->setObjectName("start");
  start_->setDefault(true);
  start_->setEnabled(false);
  connect(start_, &QPushButton::clicked, this, [this] { emit startRequested(); });
  auto* bottom = new QHBoxLayout;
  bottom->addStretch();
  bottom->addWidget(start_);
  layout->addLayout(bottom);
  set_audio_choices("default");
}

QString StartPage::audio_device() const { return audio_->currentData().toString(); }

void StartPage::set_audio_choices(const QString& device) {
  audio_->clear();
  audio_->addItem("System default", "default");
  for (const QString& name : AudioOutput::device_names()) audio_->addItem(name, name);
  audio_->addItem("No sound (null output; plays are still logged)", "null");
  const int index = audio_->findData(device);
  audio_->setCurrentIndex(index >= 0 ? index : audio_->count() - 1);
  if (index < 0) {
    const QStringList names = AudioOutput::device_names();
    set_audio_message(QString("Audio device '%1' was not found (available: %2); no sound will be heard "
                              "(null output) unless you choose another device.")
                          .arg(device, names.isEmpty() ? QString("none") : names.join(", ")));
  }
}

void StartPage::set_audio_message(const QString& message) { audio_message_->setText(message); }

void StartPage::show_problems(const QStringList& problems) {
  problems_->setPlainText(problems.join("\n"));
  problems_->setVisible(!problems.isEmpty());
  if (!problems.isEmpty()) {
    title_->setText(QString("%1 problem(s) in the protocol — fix them and load again").arg(problems.size()));
    prepared_ = false;
    calibrate_->setEnabled(false);
    update_start();
  }
}

void StartPage::show_loaded(const QString& title, int stimuli) {
  title_->setText(title);
  calibrate_->setEnabled(true);
  progress_->setRange(0, std::max(stimuli, 1));
  progress_->setValue(0);
  progress_label_->setText("rendering…");
  prepared_ = false;
  update_start();
}

void StartPage::show_progress(int done, int total, const QString& name) {
  progress_->setRange(0, std::max(total, 1));
  progress_->setValue(done);
  progress_label_->setText(QString("%1 of %2: %3").arg(done).arg(total).arg(name));
}

void StartPage::show_prepared(const QString& error) {
  prepared_ = error.isEmpty();
  if (prepared_) progress_->setValue(progress_->maximum());
  progress_label_->setText(prepared_ ? QString("all stimuli ready") : "cannot render: " + error);
  update_start();
}

void StartPage::show_participant_status(const QString& line, bool finished, const QStringList& look_alikes) {
  QString text = line;
  for (const QString& other : look_alikes)
    text += QString("%1Careful: '%2' is already in this results file; is it the same person?")
                .arg(text.isEmpty() ? "" : "\n", other);
  status_->setText(text);
  status_->setVisible(!text.isEmpty());
  finished_ = finished;
  new_session_->setVisible(finished);
  if (!finished) new_session_->setChecked(false);
  update_start();
}

void StartPage::update_start() {
  start_->setEnabled(prepared_ && !participant().isEmpty() && (!finished_ || new_session_->isChecked()));
}

}  // namespace ms::gui
