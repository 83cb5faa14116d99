// Confusion matrix heat map, painted directly (Qt Charts has no heat-map series): truth on rows,
// response on columns, white -> dark blue over 0-100 %, the percentage printed in each cell.
#include <QFontMetricsF>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "studyapp/plots/canvas.hpp"

namespace ms::plots {

using namespace detail;

namespace {

// Every rectangle and font of the picture, computed once so drawing and confusion_cell_rect agree.
struct HeatLayout {
  double scale = 1;
  QFont title_font, axis_font, tick_font;
  QRectF title, grid, colorbar;
  double cell_w = 0, cell_h = 0;
  bool rotate_columns = false;  // column labels at -45 degrees when they do not fit a cell's width
};

QFont pixel_font(double px, bool bold = false) {
  QFont f(QStringLiteral("DejaVu Sans"));
  f.setPixelSize(std::max(7, int(std::lround(px))));
  f.setBold(bold);
  return f;
}

const char* kColorbarLabel = "% of presentations (row)";

HeatLayout heat_layout(const std::vector<std::string>& labels, const PlotOptions& o) {
  HeatLayout l;
  const double w = o.width_px, h = o.height_px;
  l.scale = std::clamp(std::min(w, h) / 600.0, 0.5, 2.5);
  const double s = l.scale;
  l.title_font = pixel_font(18 * s, true);
  l.axis_font = pixel_font(14 * s);
  l.tick_font = pixel_font(12 * s);
  const QFontMetricsF title_m(l.title_font), axis_m(l.axis_font), tick_m(l.tick_font);
  double max_label_w = 0;
  for (const auto& label : labels) max_label_w = std::max(max_label_w, tick_m.horizontalAdvance(qs(label)));

  const double top = 10 * s + (o.title.empty() ? 0 : title_m.height() + 10 * s);
  l.title = QRectF(0, 10 * s, w, title_m.height());
  const double left = 10 * s + axis_m.height() + 8 * s + max_label_w + 8 * s;
  const double bar_w = 18 * s;
  const double right = 24 * s + bar_w + 6 * s + tick_m.horizontalAdvance(QStringLiteral("100")) + 8 * s +
                       axis_m.height() + 10 * s;
  auto bottom_for = [&](bool rotated) {
    const double column_labels = rotated ? (max_label_w + tick_m.height()) * std::sqrt(0.5) : tick_m.height();
    return 8 * s + column_labels + 10 * s + axis_m.height() + 10 * s;
  };
  const double n = double(std::max<std::size_t>(labels.size(), 1));
  const double grid_w = std::max(10.0, w - left - right);
  l.rotate_columns = max_label_w > grid_w / n - 6 * s;
  const double grid_h = std::max(10.0, h - top - bottom_for(l.rotate_columns));
  l.grid = QRectF(left, top, grid_w, grid_h);
  l.cell_w = grid_w / n;
  l.cell_h = grid_h / n;
  l.colorbar = QRectF(left + grid_w + 24 * s, top, bar_w, grid_h);
  return l;
}

// ColorBrewer "Blues" through three stops: readable numbers in both the lightest and darkest cells.
QColor blues(double percent) {
  const double t = std::clamp(percent / 100.0, 0.0, 1.0);
  const double stops[3][3] = {{247, 251, 255}, {107, 174, 214}, {8, 48, 107}};
  const int k = t < 0.5 ? 0 : 1;
  const double u = t < 0.5 ? t / 0.5 : (t - 0.5) / 0.5;
  auto mix = [&](int c) { return int(std::lround(stops[k][c] + u * (stops[k + 1][c] - stops[k][c]))); };
  return QColor(mix(0), mix(1), mix(2));
}

QString percent_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, std::abs(v - std::round(v)) < 0.05 ? "%.0f" : "%.1f", v);
  return QString::fromLatin1(buf);
}

}  // namespace

RectPx confusion_cell_rect(const std::vector<std::string>& labels, const PlotOptions& options, std::size_t row,
                           std::size_t col) {
  if (row >= labels.size() || col >= labels.size())
    throw std::invalid_argument("confusion_cell_rect: cell outside the matrix");
  ensure_app();  // font metrics
  const HeatLayout l = heat_layout(labels, options);
  return {l.grid.left() + double(col) * l.cell_w, l.grid.top() + double(row) * l.cell_h, l.cell_w, l.cell_h};
}

void confusion_heatmap(const std::string& path, const std::vector<std::string>& labels,
                       const std::vector<std::vector<double>>& matrix_percent, const PlotOptions& options) {
  check_output_path(path);
  require_size(matrix_percent.size(), labels.size(), "confusion_heatmap: matrix rows");
  for (const auto& row : matrix_percent) require_size(row.size(), labels.size(), "confusion_heatmap: matrix columns");
  ensure_app();
  const HeatLayout l = heat_layout(labels, options);
  const std::size_t n = labels.size();
  const double s = l.scale;

  write_picture(path, options, [&](QPainter& p) {
    const QFontMetricsF axis_m(l.axis_font), tick_m(l.tick_font);
    if (!options.title.empty()) {
      p.setFont(l.title_font);
      p.setPen(Qt::black);
      p.drawText(l.title, Qt::AlignHCenter | Qt::AlignVCenter, qs(options.title));
    }
    // Cells, each with its number; the text is white on dark cells.
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c) {
        const QRectF cell(l.grid.left() + double(c) * l.cell_w, l.grid.top() + double(r) * l.cell_h, l.cell_w, l.cell_h);
        const double v = matrix_percent[r][c];
        const bool ok = std::isfinite(v);
        const QColor fill = ok ? blues(v) : QColor(225, 225, 225);
        p.fillRect(cell, fill);
        const QString text = ok ? percent_text(v) : QStringLiteral("–");
        QFont f = pixel_font(std::min({16 * s, l.cell_h * 0.4, 100.0}));
        // Shrink until the number fits the cell with a margin.
        while (f.pixelSize() > 6 && QFontMetricsF(f).horizontalAdvance(text) > l.cell_w * 0.85)
          f.setPixelSize(f.pixelSize() - 1);
        p.setFont(f);
        p.setPen(fill.lightnessF() < 0.55 ? Qt::white : QColor(20, 20, 20));
        p.drawText(cell, Qt::AlignCenter, text);
      }
    // Grid lines, then the diagonal (correct answers) outlined.
    p.setPen(QPen(Qt::white, std::max(1.0, 1.5 * s)));
    for (std::size_t k = 1; k < n; ++k) {
      const double x = l.grid.left() + double(k) * l.cell_w, y = l.grid.top() + double(k) * l.cell_h;
      p.drawLine(QPointF(x, l.grid.top()), QPointF(x, l.grid.bottom()));
      p.drawLine(QPointF(l.grid.left(), y), QPointF(l.grid.right(), y));
    }
    p.setPen(QPen(QColor(60, 60, 60), std::max(1.0, 1.2 * s)));
    p.setBrush(Qt::NoBrush);
    p.drawRect(l.grid);
    // Labels: truth names left of the rows, response names under the columns.
    p.setFont(l.tick_font);
    p.setPen(Qt::black);
    for (std::size_t k = 0; k < n; ++k) {
      const QRectF row_box(0, l.grid.top() + double(k) * l.cell_h, l.grid.left() - 8 * s, l.cell_h);
      p.drawText(row_box, Qt::AlignRight | Qt::AlignVCenter, qs(labels[k]));
      const double cx = l.grid.left() + (double(k) + 0.5) * l.cell_w;
      if (l.rotate_columns) {
        p.save();
        p.translate(cx + tick_m.height() * 0.3, l.grid.bottom() + 6 * s);
        p.rotate(-45);
        const double tw = tick_m.horizontalAdvance(qs(labels[k]));
        p.drawText(QRectF(-tw - 2, 0, tw + 2, tick_m.height()), Qt::AlignRight | Qt::AlignVCenter, qs(labels[k]));
        p.restore();
      } else {
        p.drawText(QRectF(cx - l.cell_w / 2, l.grid.bottom() + 6 * s, l.cell_w, tick_m.height()), Qt::AlignCenter,
                   qs(labels[k]));
      }
    }
    // Axis titles.
    p.setFont(l.axis_font);
    const QString x_title = qs(options.x_label.empty() ? "Response" : options.x_label);
    const QString y_title = qs(options.y_label.empty() ? "Presented (truth)" : options.y_label);
    p.drawText(QRectF(l.grid.left(), options.height_px - 10 * s - axis_m.height(), l.grid.width(), axis_m.height()),
               Qt::AlignCenter, x_title);
    p.save();
    p.translate(10 * s, l.grid.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-l.grid.height() / 2, 0, l.grid.height(), axis_m.height()), Qt::AlignCenter, y_title);
    p.restore();
    // Colour bar with ticks every 25 %.
    const QRectF bar = l.colorbar;
    const int steps = 100;
    for (int k = 0; k < steps; ++k) {
      const double y0 = bar.bottom() - bar.height() * (k + 1) / steps;
      p.fillRect(QRectF(bar.left(), y0, bar.width(), bar.height() / steps + 0.6), blues(100.0 * (k + 0.5) / steps));
    }
    p.setPen(QPen(QColor(60, 60, 60), 1));
    p.drawRect(bar);
    p.setFont(l.tick_font);
    for (int v = 0; v <= 100; v += 25) {
      const double y = bar.bottom() - bar.height() * v / 100.0;
      p.drawLine(QPointF(bar.right(), y), QPointF(bar.right() + 4 * s, y));
      p.drawText(QRectF(bar.right() + 6 * s, y - tick_m.height() / 2, 60 * s, tick_m.height()),
                 Qt::AlignLeft | Qt::AlignVCenter, QString::number(v));
    }
    p.save();
    p.translate(bar.right() + 6 * s + tick_m.horizontalAdvance(QStringLiteral("100")) + 8 * s, bar.center().y());
    p.rotate(90);
    p.setFont(l.axis_font);
    p.drawText(QRectF(-bar.height() / 2, -axis_m.height(), bar.height(), axis_m.height()), Qt::AlignCenter,
               QString::fromUtf8(kColorbarLabel));
    p.restore();
  });
}

}  // namespace ms::plots
