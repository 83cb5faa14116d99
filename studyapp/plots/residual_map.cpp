// Residual map: a time x Bark-band matrix of dB differences (model - measured) painted as a diverging
// heat map (blue: model too quiet, red: model too loud, grey: below the floor in both), with a colour bar.
#include <QFontMetricsF>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "studyapp/plots/canvas.hpp"

namespace ms::plots {

using namespace detail;

namespace {

QColor diverging(double v, double limit) {
  const double t = std::clamp(v / limit, -1.0, 1.0);
  const double blue[3] = {33, 102, 172}, white[3] = {247, 247, 247}, red[3] = {178, 24, 43};
  const double* end = t < 0 ? blue : red;
  const double u = std::abs(t);
  auto mix = [&](int c) { return int(std::lround(white[c] + u * (end[c] - white[c]))); };
  return QColor(mix(0), mix(1), mix(2));
}

}  // namespace

void residual_map(const std::string& path, const std::vector<std::vector<double>>& diff_db_by_band,
                  double duration_s, double limit_db, const PlotOptions& options) {
  check_output_path(path);
  if (diff_db_by_band.empty()) throw std::invalid_argument("residual_map: no bands");
  const std::size_t bands = diff_db_by_band.size(), frames = diff_db_by_band.front().size();
  for (const auto& row : diff_db_by_band) require_size(row.size(), frames, "residual_map: frames per band");
  ensure_app();
  write_picture(path, options, [&](QPainter& p) {
    const double s = std::clamp(std::min(options.width_px, options.height_px) / 600.0, 0.5, 2.5);
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setPixelSize(std::max(7, int(std::lround(12 * s))));
    const QFontMetricsF m(font);
    const double top = (options.title.empty() ? 10 : 40) * s, left = 60 * s, bottom = 50 * s, right = 90 * s;
    const QRectF grid(left, top, options.width_px - left - right, options.height_px - top - bottom);
    p.setFont(font);
    if (!options.title.empty())
      p.drawText(QRectF(0, 8 * s, options.width_px, 24 * s), Qt::AlignCenter, qs(options.title));
    const double cw = grid.width() / double(std::max<std::size_t>(frames, 1)), ch = grid.height() / double(bands);
    for (std::size_t b = 0; b < bands; ++b)
      for (std::size_t f = 0; f < frames; ++f) {
        const double v = diff_db_by_band[b][f];
        const QRectF cell(grid.left() + double(f) * cw, grid.bottom() - double(b + 1) * ch, cw + 0.5, ch + 0.5);
        p.fillRect(cell, std::isfinite(v) ? diverging(v, limit_db) : QColor(200, 200, 200));
      }
    p.setPen(QPen(QColor(60, 60, 60), 1));
    p.drawRect(grid);
    // Ticks: Bark bands every 4, time in 5 steps.
    for (std::size_t b = 0; b < bands; b += 4) {
      const double y = grid.bottom() - (double(b) + 0.5) * ch;
      p.drawText(QRectF(0, y - m.height() / 2, left - 6 * s, m.height()), Qt::AlignRight | Qt::AlignVCenter,
                 QString::number(b));
    }
    for (int k = 0; k <= 5; ++k) {
      const double x = grid.left() + grid.width() * k / 5.0;
      p.drawLine(QPointF(x, grid.bottom()), QPointF(x, grid.bottom() + 4 * s));
      p.drawText(QRectF(x - 30 * s, grid.bottom() + 6 * s, 60 * s, m.height()), Qt::AlignCenter,
                 QString::number(duration_s * k / 5.0, 'g', 3));
    }
    p.drawText(QRectF(grid.left(), options.height_px - m.height() - 6 * s, grid.width(), m.height()), Qt::AlignCenter,
               qs(options.x_label.empty() ? "time after the onset [s]" : options.x_label));
    p.save();
    p.translate(8 * s, grid.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-grid.height() / 2, 0, grid.height(), m.height()), Qt::AlignCenter,
               qs(options.y_label.empty() ? "Bark band" : options.y_label));
    p.restore();
    // Colour bar.
    const QRectF bar(grid.right() + 16 * s, grid.top(), 16 * s, grid.height());
    for (int k = 0; k < 100; ++k) {
      const double v = -limit_db + 2 * limit_db * (k + 0.5) / 100.0;
      p.fillRect(QRectF(bar.left(), bar.bottom() - bar.height() * (k + 1) / 100.0, bar.width(), bar.height() / 100.0 + 0.6),
                 diverging(v, limit_db));
    }
    p.drawRect(bar);
    for (int k = 0; k <= 4; ++k) {
      const double y = bar.bottom() - bar.height() * k / 4.0;
      p.drawText(QRectF(bar.right() + 4 * s, y - m.height() / 2, 60 * s, m.height()), Qt::AlignLeft | Qt::AlignVCenter,
                 QString::number(-limit_db + 2 * limit_db * k / 4.0) + " dB");
    }
  });
}

}  // namespace ms::plots
