#include "studyapp/plots/time_band_map.hpp"

#include <QFontMetricsF>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "studyapp/plots/canvas.hpp"

namespace ms::plots::detail {

void write_time_band_map(const std::string& path, const TimeBandMap& map, const PlotOptions& options,
                         const char* what) {
  check_output_path(path);
  if (!map.cells || map.cells->empty()) throw std::invalid_argument(std::string(what) + ": no bands");
  const auto& cells = *map.cells;
  const std::size_t bands = cells.size(), frames = cells.front().size();
  for (const auto& row : cells) require_size(row.size(), frames, what);
  ensure_app();
  write_picture(path, options, [&](QPainter& p) {
    const double s = std::clamp(std::min(options.width_px, options.height_px) / 600.0, 0.5, 2.5);
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPixelSize(std::max(7, int(std::lround(12 * s))));
    const QFontMetricsF m(font);
    const double top = (options.title.empty() ? 10 : 40) * s, left = 60 * s, bottom = 50 * s, right = 100 * s;
    const QRectF grid(left, top, options.width_px - left - right, options.height_px - top - bottom);
    p.setFont(font);
    if (!options.title.empty())
      p.drawText(QRectF(0, 8 * s, options.width_px, 24 * s), Qt::AlignCenter, qs(options.title));
    const double cw = grid.width() / double(std::max<std::size_t>(frames, 1)), ch = grid.height() / double(bands);
    for (std::size_t b = 0; b < bands; ++b)
      for (std::size_t f = 0; f < frames; ++f) {
        const double v = cells[b][f];
        const QRectF cell(grid.left() + double(f) * cw, grid.bottom() - double(b + 1) * ch, cw + 0.5, ch + 0.5);
        p.fillRect(cell, std::isfinite(v) ? map.colour(v) : QColor(200, 200, 200));
      }
    p.setPen(QPen(QColor(60, 60, 60), 1));
    p.drawRect(grid);
    for (const auto& [at_bands, text] : map.band_ticks) {
      const double y = grid.bottom() - at_bands * ch;
      p.drawLine(QPointF(grid.left() - 4 * s, y), QPointF(grid.left(), y));
      p.drawText(QRectF(0, y - m.height() / 2, left - 6 * s, m.height()), Qt::AlignRight | Qt::AlignVCenter, qs(text));
    }
    for (int k = 0; k <= 5; ++k) {
      const double x = grid.left() + grid.width() * k / 5.0;
      p.drawLine(QPointF(x, grid.bottom()), QPointF(x, grid.bottom() + 4 * s));
      p.drawText(QRectF(x - 30 * s, grid.bottom() + 6 * s, 60 * s, m.height()), Qt::AlignCenter,
                 QString::number(map.duration_s * k / 5.0, 'g', 3));
    }
    p.drawText(QRectF(grid.left(), options.height_px - m.height() - 6 * s, grid.width(), m.height()), Qt::AlignCenter,
               qs(options.x_label.empty() ? "time after the onset [s]" : options.x_label));
    p.save();
    p.translate(8 * s, grid.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-grid.height() / 2, 0, grid.height(), m.height()), Qt::AlignCenter,
               qs(options.y_label.empty() ? map.band_label : options.y_label));
    p.restore();
    const QRectF bar(grid.right() + 16 * s, grid.top(), 16 * s, grid.height());
    const double span = map.bar_hi - map.bar_lo;
    for (int k = 0; k < 100; ++k)
      p.fillRect(QRectF(bar.left(), bar.bottom() - bar.height() * (k + 1) / 100.0, bar.width(), bar.height() / 100.0 + 0.6),
                 map.colour(map.bar_lo + span * (k + 0.5) / 100.0));
    p.drawRect(bar);
    for (int k = 0; k <= 4; ++k) {
      const double y = bar.bottom() - bar.height() * k / 4.0;
      p.drawText(QRectF(bar.right() + 4 * s, y - m.height() / 2, 80 * s, m.height()), Qt::AlignLeft | Qt::AlignVCenter,
                 QString::number(map.bar_lo + span * k / 4.0, 'g', 3) + qs(map.bar_unit));
    }
  });
}

}  // namespace ms::plots::detail
