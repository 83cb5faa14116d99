// Loudness image: a time x Bark matrix in sone painted as a heat map (white -> dark red for a
// loudness image, blue/white/red for a difference of two), with a colour bar in sone.
#include <QFontMetricsF>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "studyapp/plots/canvas.hpp"

namespace ms::plots {

using namespace detail;

namespace {

QColor mix(const double (&from)[3], const double (&to)[3], double u) {
  auto c = [&](int k) { return int(std::lround(from[k] + u * (to[k] - from[k]))); };
  return QColor(c(0), c(1), c(2));
}

// Sequential for 0..limit (a loudness), diverging for -limit..limit (a difference).
QColor colour(double v, double limit, bool difference) {
  static const double white[3] = {255, 255, 255}, blue[3] = {33, 102, 172}, red[3] = {178, 24, 43},
                      dark[3] = {103, 0, 13};
  if (!std::isfinite(v)) return QColor(200, 200, 200);
  if (difference) {
    const double t = std::clamp(v / limit, -1.0, 1.0);
    return mix(white, t < 0 ? blue : red, std::abs(t));
  }
  return mix(white, dark, std::clamp(v / limit, 0.0, 1.0));
}

}  // namespace

void loudness_image(const std::string& path, const std::vector<std::vector<double>>& sone_by_band, double hop_s,
                    double band_bark, bool difference, const PlotOptions& options) {
  check_output_path(path);
  if (sone_by_band.empty()) throw std::invalid_argument("loudness_image: no bands");
  const std::size_t bands = sone_by_band.size(), frames = sone_by_band.front().size();
  for (const auto& row : sone_by_band) require_size(row.size(), frames, "loudness_image: frames per band");
  double limit = 0.0;
  for (const auto& row : sone_by_band)
    for (double v : row)
      if (std::isfinite(v)) limit = std::max(limit, std::abs(v));
  if (!(limit > 0.0)) limit = 1.0;
  const double duration_s = hop_s * double(frames);
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
        const QRectF cell(grid.left() + double(f) * cw, grid.bottom() - double(b + 1) * ch, cw + 0.5, ch + 0.5);
        p.fillRect(cell, colour(sone_by_band[b][f], limit, difference));
      }
    p.setPen(QPen(QColor(60, 60, 60), 1));
    p.drawRect(grid);
    // Ticks: every 5 Bark, time in 5 steps.
    const double top_bark = double(bands) * band_bark;
    for (double z = 0.0; z <= top_bark + 1e-9; z += 5.0) {
      const double y = grid.bottom() - grid.height() * z / top_bark;
      p.drawLine(QPointF(grid.left() - 4 * s, y), QPointF(grid.left(), y));
      p.drawText(QRectF(0, y - m.height() / 2, left - 6 * s, m.height()), Qt::AlignRight | Qt::AlignVCenter,
                 QString::number(z));
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
               qs(options.y_label.empty() ? "critical-band rate [Bark]" : options.y_label));
    p.restore();
    // Colour bar.
    const QRectF bar(grid.right() + 16 * s, grid.top(), 16 * s, grid.height());
    const double lo = difference ? -limit : 0.0;
    for (int k = 0; k < 100; ++k) {
      const double v = lo + (limit - lo) * (k + 0.5) / 100.0;
      p.fillRect(QRectF(bar.left(), bar.bottom() - bar.height() * (k + 1) / 100.0, bar.width(), bar.height() / 100.0 + 0.6),
                 colour(v, limit, difference));
    }
    p.drawRect(bar);
    for (int k = 0; k <= 4; ++k) {
      const double y = bar.bottom() - bar.height() * k / 4.0;
      p.drawText(QRectF(bar.right() + 4 * s, y - m.height() / 2, 80 * s, m.height()), Qt::AlignLeft | Qt::AlignVCenter,
                 QString::number(lo + (limit - lo) * k / 4.0, 'g', 3) + " sone");
    }
  });
}

}  // namespace ms::plots
