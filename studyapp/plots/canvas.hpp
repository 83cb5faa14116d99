// Internal to modalstudy_plots: the headless QApplication, PNG/SVG output, the QChart canvas, and the
// small drawing helpers (palette, label placement) the plot kinds share.
#pragma once
#include <QtCharts/QChart>
#include <QtCharts/QLogValueAxis>
#include <QtCharts/QValueAxis>
#include <QColor>
#include <QFont>
#include <QGraphicsScene>
#include <QPainter>
#include <QString>

#include <functional>
#include <string>
#include <vector>

#include "studyapp/plots/plots.hpp"

namespace ms::plots::detail {

// Creates the QApplication on first use (offscreen platform when there is no display).
void ensure_app();

QString qs(const std::string& s);

// Paints `paint` on a white canvas of the options' size and writes PNG or SVG atomically to `path`.
void write_picture(const std::string& path, const PlotOptions& options,
                   const std::function<void(QPainter&)>& paint);

// Throws std::invalid_argument naming `what` unless n == expected.
void require_size(std::size_t n, std::size_t expected, const char* what);

// Colours that survive greyscale printing and colour-blindness reasonably (Tableau 10).
QColor palette(std::size_t i);

// The span of the finite (and, for log axes, positive) values seen.
struct Range {
  double lo = 0, hi = 0;
  bool empty = true;
  void add(double v, bool positive_only = false);
};

// Axes with a title and readable labels. A linear axis gets "nice" round ticks over [lo, hi] padded by
// pad_fraction; a log axis spans whole decades (labels sit at powers of 10 only).
QValueAxis* add_value_axis(QChart& chart, Qt::Alignment side, const QString& title, Range range,
                           double pad_fraction = 0.05);
QLogValueAxis* add_log_axis(QChart& chart, Qt::Alignment side, const QString& title, Range range);

// A QChart laid out at the options' size in its own scene; after layout(), chart().mapToPosition()
// gives pixel positions, which annotations (labels, stems, error bars) use.
class ChartCanvas {
 public:
  explicit ChartCanvas(const PlotOptions& options);
  QChart& chart() { return *chart_; }
  void layout();
  // Renders the chart, then `annotate` on top (in the same pixel coordinates), and writes the file.
  void write(const std::string& path, const std::function<void(QPainter&)>& annotate = {});

 private:
  PlotOptions options_;
  QGraphicsScene scene_;
  QChart* chart_;  // owned by scene_
};

// Greedy label placement: each text goes at the first of 8 positions around its anchor that overlaps
// neither an earlier label nor any anchor marker; the least-overlapping position otherwise.
struct PlacedLabel {
  QPointF anchor;  // pixel position of the point
  QString text;
  QColor color;
  QFont font;
};
void draw_labels(QPainter& painter, const std::vector<PlacedLabel>& labels, const QRectF& bounds,
                 double marker_radius_px);

}  // namespace ms::plots::detail
