// Masking plot: mode levels as stems (kept / dropped), the masking threshold and the threshold in
// quiet at each mode's frequency, on a log-frequency axis.
#include <QtCharts/QLegend>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "studyapp/plots/canvas.hpp"

namespace ms::plots {

using namespace detail;

void masking_plot(const std::string& path, const std::vector<double>& freq_hz, const std::vector<double>& level_db,
                  const std::vector<double>& masking_threshold_db, const std::vector<double>& quiet_threshold_db,
                  const std::vector<bool>& kept, const PlotOptions& options) {
  check_output_path(path);
  const std::size_t n = freq_hz.size();
  require_size(level_db.size(), n, "masking_plot: level_db");
  require_size(masking_threshold_db.size(), n, "masking_plot: masking_threshold_db");
  require_size(quiet_threshold_db.size(), n, "masking_plot: quiet_threshold_db");
  require_size(kept.size(), n, "masking_plot: kept");
  ensure_app();
  ChartCanvas canvas(options);
  QChart& chart = canvas.chart();

  // Curves join the modes in frequency order.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return freq_hz[a] < freq_hz[b]; });

  const QColor kept_color = palette(0), dropped_color = palette(3), mask_color = palette(1), quiet_color = palette(2);
  Range xr, yr, curve_range;
  std::size_t n_kept = 0, n_dropped = 0;
  auto* kept_points = new QScatterSeries;
  auto* dropped_points = new QScatterSeries;
  for (std::size_t i : order) {
    const double f = freq_hz[i], l = level_db[i];
    if (!std::isfinite(f) || f <= 0) continue;
    xr.add(f, true);
    if (!std::isfinite(l)) continue;
    (kept[i] ? kept_points : dropped_points)->append(f, l);
    (kept[i] ? n_kept : n_dropped) += 1;
    yr.add(l);
  }
  kept_points->setName(QStringLiteral("kept mode (%1)").arg(n_kept));
  dropped_points->setName(QStringLiteral("dropped mode (%1)").arg(n_dropped));
  for (auto [series, color] : {std::pair{kept_points, kept_color}, std::pair{dropped_points, dropped_color}}) {
    series->setColor(color);
    series->setBorderColor(color.darker(130));
    series->setMarkerSize(7);
  }
  dropped_points->setMarkerShape(QScatterSeries::MarkerShapeRectangle);

  // A threshold curve, broken where the threshold is -inf (no masker), each piece its own series
  // with only the first in the legend.
  auto add_curve = [&](const std::vector<double>& db, const QString& name, const QPen& pen) {
    QLineSeries* current = nullptr;
    bool first = true;
    for (std::size_t i : order) {
      const double f = freq_hz[i], v = db[i];
      if (!std::isfinite(f) || f <= 0 || !std::isfinite(v)) {
        current = nullptr;
        continue;
      }
      if (current == nullptr) {
        current = new QLineSeries;
        current->setName(name);
        current->setPen(pen);
        chart.addSeries(current);
        const auto markers = chart.legend()->markers(current);
        if (!first && !markers.isEmpty()) markers.front()->setVisible(false);
        first = false;
      }
      current->append(f, v);
      curve_range.add(v);
    }
  };
  add_curve(masking_threshold_db, QStringLiteral("masking threshold from the other modes"), QPen(mask_color, 2.0));
  QPen quiet_pen(quiet_color, 2.0);
  quiet_pen.setStyle(Qt::DashLine);
  add_curve(quiet_threshold_db, QStringLiteral("threshold in quiet"), quiet_pen);
  chart.addSeries(dropped_points);
  chart.addSeries(kept_points);

  // The level axis follows the modes; thresholds widen it by at most 20 dB above and 40 dB below
  // (the threshold in quiet climbs steeply near 20 kHz and would squash the modes), the rest is clipped.
  if (!curve_range.empty) {
    if (yr.empty) {
      yr = curve_range;
    } else {
      yr.add(std::min(curve_range.hi, yr.hi + 20));
      yr.add(std::max(curve_range.lo, yr.lo - 40));
    }
  }
  auto* x_axis = add_log_axis(chart, Qt::AlignBottom, qs(options.x_label.empty() ? "Frequency [Hz]" : options.x_label), xr);
  auto* y_axis = add_value_axis(chart, Qt::AlignLeft, qs(options.y_label.empty() ? "Level [dB SPL]" : options.y_label), yr, 0.06);
  for (auto* s : chart.series()) {
    s->attachAxis(x_axis);
    s->attachAxis(y_axis);
  }

  canvas.write(path, [&](QPainter& p) {
    // Stems from the bottom of the plot up to each mode's level, under the markers' colours.
    const QRectF plot = chart.plotArea();
    p.setClipRect(plot);
    for (std::size_t i = 0; i < n; ++i) {
      const double f = freq_hz[i], l = level_db[i];
      if (!std::isfinite(f) || f <= 0 || !std::isfinite(l)) continue;
      const QPointF top = chart.mapToPosition(QPointF(f, l), kept_points);
      QColor c = kept[i] ? kept_color : dropped_color;
      c.setAlpha(150);
      p.setPen(QPen(c, 1.3));
      p.drawLine(QPointF(top.x(), plot.bottom()), top);
    }
  });
}

}  // namespace ms::plots
