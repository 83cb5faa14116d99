// ExperimenterWindow: sessions table (ResultsStore::session_summaries), Export (export_results), pictures.
#include "studyapp/gui/experimenter_window.hpp"

#include <QDateTime>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPixmap>
#include <QPushButton>
#include <QFile>
#include <QScrollArea>

#include "studyapp/core/export.hpp"
#include "studyapp/core/results_store.hpp"
#include "studyapp/gui/analysis_pictures.hpp"
#include "studyapp/plots/plots.hpp"

namespace ms::gui {

namespace {

QString when(std::int64_t ms) { return QDateTime::fromMSecsSinceEpoch(ms).toString("yyyy-MM-dd hh:mm"); }

}  // namespace

ExperimenterWindow::ExperimenterWindow(const QString& db_path, QWidget* parent) : QWidget(parent) {
  setWindowTitle("studyapp — experimenter view");
  resize(860, 640);
  auto* layout = new QVBoxLayout(this);
  auto* row = new QHBoxLayout;
  path_ = new QLineEdit(db_path, this);
  path_->setObjectName("dbPath");
  auto* browse = new QPushButton("Open…", this);
  auto* reload = new QPushButton("Reload", this);
  reload->setObjectName("reload");
  auto* exporter = new QPushButton("Export…", this);
  exporter->setObjectName("export");
  row->addWidget(new QLabel("Results", this));
  row->addWidget(path_, 1);
  row->addWidget(browse);
  row->addWidget(reload);
  row->addWidget(exporter);
  layout->addLayout(row);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString p = QFileDialog::getOpenFileName(this, "Results database", path_->text(), "SQLite (*.sqlite *.db)");
    if (!p.isEmpty()) open_db(p);
  });
  connect(reload, &QPushButton::clicked, this, [this] { open_db(path_->text()); });
  connect(exporter, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, "Export into", QFileInfo(path_->text()).absolutePath());
    if (!dir.isEmpty()) export_to(dir);
  });

  auto* tabs = new QTabWidget(this);
  table_ = new QTableWidget(0, 8, this);
  table_->setObjectName("sessions");
  table_->setHorizontalHeaderLabels(
      {"study", "participant", "session", "started", "finished", "answered", "completion", "answered by"});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  tabs->addTab(table_, "Participants and sessions");
  auto* scroll = new QScrollArea(this);
  pictures_ = new QWidget;
  pictures_layout_ = new QVBoxLayout(pictures_);
  scroll->setWidget(pictures_);
  scroll->setWidgetResizable(true);
  tabs->addTab(scroll, "Analysis pictures");
  layout->addWidget(tabs, 1);
  status_ = new QLabel(this);
  status_->setObjectName("status");
  status_->setWordWrap(true);
  layout->addWidget(status_);
  if (!db_path.isEmpty()) open_db(db_path);
}

bool ExperimenterWindow::open_db(const QString& path) {
  path_->setText(path);
  table_->setRowCount(0);
  try {
    const ResultsStore store(path.toStdString(), ResultsStore::Mode::read_only);
    const auto sessions = store.session_summaries();
    table_->setRowCount(static_cast<int>(sessions.size()));
    for (int r = 0; r < static_cast<int>(sessions.size()); ++r) {
      const SessionSummary& s = sessions[static_cast<std::size_t>(r)];
      const double pct = s.trials ? 100.0 * static_cast<double>(s.responses) / static_cast<double>(s.trials) : 0.0;
      const QStringList cells{QString::fromStdString(s.study), QString::fromStdString(s.participant_code),
                              QString::number(s.session), when(s.started_ms),
                              s.finished_ms ? when(*s.finished_ms) : QString("—"),
                              QString("%1 / %2").arg(s.responses).arg(s.trials), QString("%1 %").arg(pct, 0, 'f', 0),
                              s.autopilot ? QString("simulated (autopilot)") : QString("participant")};
      for (int c = 0; c < cells.size(); ++c) table_->setItem(r, c, new QTableWidgetItem(cells[c]));
    }
    status_->setText(QString("%1 session(s)").arg(sessions.size()));
    draw_pictures(store);
    return true;
  } catch (const std::exception& e) {
    status_->setText(QString("Cannot read %1: %2").arg(path, QString::fromStdString(e.what())));
    return false;
  }
}

void ExperimenterWindow::draw_pictures(const ResultsStore& store) {
  while (QLayoutItem* item = pictures_layout_->takeAt(0)) {
    delete item->widget();
    delete item;
  }
  picture_count_ = 0;
  for (const Picture& p :
       draw_analysis_pictures(store.response_rows(), picture_dir_.path().toStdString(), stored_protocols(store))) {
    auto* heading = new QHBoxLayout;
    heading->addWidget(new QLabel("<b>" + QString::fromStdString(p.title) + "</b>", pictures_), 1);
    auto* save = new QPushButton("Save as PNG or SVG…", pictures_);
    save->setObjectName("savePicture");
    const QString source = QString::fromStdString(p.path);
    connect(save, &QPushButton::clicked, this, [this, source] {
      const QString to = QFileDialog::getSaveFileName(this, "Save picture", QFileInfo(source).fileName(),
                                                      "PNG (*.png);;SVG (*.svg)");
      if (!to.isEmpty()) save_picture(source, to);
    });
    save->setProperty("png", source);
    heading->addWidget(save);
    pictures_layout_->addLayout(heading);
    auto* image = new QLabel(pictures_);
    image->setObjectName("picture");
    image->setPixmap(QPixmap(QString::fromStdString(p.path)));
    pictures_layout_->addWidget(image);
    ++picture_count_;
  }
  if (picture_count_ == 0)
    pictures_layout_->addWidget(new QLabel("No A/B, MUSHRA, magnitude, identify or staircase responses yet.", pictures_));
  pictures_layout_->addStretch();
}

bool ExperimenterWindow::save_picture(const QString& png, const QString& to) {
  try {
    const bool svg = plots::check_output_path(to.toStdString());  // .png or .svg, else a one-line refusal
    const QString source = svg ? png.left(png.size() - 4) + ".svg" : png;  // drawn as both
    QFile::remove(to);
    if (!QFile::copy(source, to)) throw std::runtime_error("cannot write " + to.toStdString());
    status_->setText("Saved " + to);
    return true;
  } catch (const std::exception& e) {
    status_->setText(QString("Cannot save the picture: %1").arg(QString::fromStdString(e.what())));
    return false;
  }
}

bool ExperimenterWindow::export_to(const QString& dir) {
  try {
    const ExportSummary s = export_results(path_->text().toStdString(), dir.toStdString());
    status_->setText(QString("Exported %1 responses to %2").arg(s.responses).arg(QString::fromStdString(s.csv_path)));
    return true;
  } catch (const std::exception& e) {
    status_->setText(QString("Export failed: %1").arg(QString::fromStdString(e.what())));
    return false;
  }
}

}  // namespace ms::gui
