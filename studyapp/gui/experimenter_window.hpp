// The experimenter view of a results database: participants and sessions with their completion, the
// export to tidy CSV (modalstudy export) and the analysis pictures (confusion heat maps, MUSHRA box plots).
#pragma once
#include <QLabel>
#include <QLineEdit>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QVBoxLayout>
#include <QWidget>

namespace ms {
class ResultsStore;
}

namespace ms::gui {

class ExperimenterWindow : public QWidget {
  Q_OBJECT

 public:
  explicit ExperimenterWindow(const QString& db_path, QWidget* parent = nullptr);

  // Reads the database; false (with the reason shown) when it cannot be read.
  bool open_db(const QString& path);
  // Exports into `dir`; false (with the reason shown) on failure.
  bool export_to(const QString& dir);
  // Saves a drawn picture (its PNG) as `to`: .png copied, .svg embedding it; false (reason shown) on failure.
  bool save_picture(const QString& png, const QString& to);
  QTableWidget& sessions() { return *table_; }
  int picture_count() const { return picture_count_; }

 private:
  void draw_pictures(const ResultsStore& store);

  QLineEdit* path_;
  QTableWidget* table_;
  QLabel* status_;
  QWidget* pictures_;
  QVBoxLayout* pictures_layout_;
  QTemporaryDir picture_dir_;
  int picture_count_ = 0;
};

}  // namespace ms::gui
