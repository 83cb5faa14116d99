// MDS perceptual map: labelled scatter, equal scales on both axes, optional Procrustes-aligned overlay.
#include <QtCharts/QLegendMarker>
#include <QtCharts/QScatterSeries>

#include <complex>
#include <stdexcept>

#include "studyapp/plots/canvas.hpp"

namespace ms::plots {

using namespace detail;

std::vector<XY> procrustes_align(const std::vector<XY>& target, const std::vector<XY>& source) {
  require_size(source.size(), target.size(), "procrustes_align: source points");
  const std::size_t n = target.size();
  if (n == 0) return {};
  // Points as complex numbers: a similarity is z -> c w + t (rotation) or c conj(w) + t (reflection).
  using C = std::complex<double>;
  C mean_t = 0, mean_s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mean_t += C(target[i].x, target[i].y);
    mean_s += C(source[i].x, source[i].y);
  }
  mean_t /= double(n);
  mean_s /= double(n);
  C cross_rot = 0, cross_ref = 0;
  double norm_s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const C z = C(target[i].x, target[i].y) - mean_t, w = C(source[i].x, source[i].y) - mean_s;
    cross_rot += z * std::conj(w);
    cross_ref += z * w;
    norm_s += std::norm(w);
  }
  // Least squares: c = sum z conj(w') / sum |w'|^2 with w' = w or conj(w); the residual is
  // sum|z|^2 - |sum z conj(w')|^2 / sum|w|^2, so the larger cross term wins.
  const bool reflect = std::abs(cross_ref) > std::abs(cross_rot);
  const C c = norm_s > 0 ? (reflect ? cross_ref : cross_rot) / norm_s : C(0);
  std::vector<XY> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    C w = C(source[i].x, source[i].y) - mean_s;
    if (reflect) w = std::conj(w);
    const C z = c * w + mean_t;
    out[i] = {z.real(), z.imag()};
  }
  return out;
}

void mds_map(const std::string& path, const std::vector<XY>& points, const std::vector<std::string>& labels,
             const PlotOptions& options, const std::optional<MapOverlay>& overlay) {
  check_output_path(path);
  if (!labels.empty()) require_size(labels.size(), points.size(), "mds_map: labels");
  std::vector<XY> second;
  if (overlay) {
    require_size(overlay->points.size(), points.size(), "mds_map: overlay points");
    if (!overlay->labels.empty()) require_size(overlay->labels.size(), points.size(), "mds_map: overlay labels");
    second = overlay->procrustes_align ? procrustes_align(points, overlay->points) : overlay->points;
  }
  ensure_app();

  ChartCanvas canvas(options);
  QChart& chart = canvas.chart();
  Range xr, yr;
  auto* base = new QScatterSeries;
  base->setName(overlay ? qs(overlay->base_name) : QStringLiteral("stimuli"));
  base->setMarkerSize(11);
  base->setColor(palette(0));
  base->setBorderColor(palette(0).darker(140));
  for (const auto& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    base->append(p.x, p.y);
    xr.add(p.x);
    yr.add(p.y);
  }
  QScatterSeries* over = nullptr;
  if (overlay) {
    over = new QScatterSeries;
    over->setName(qs(overlay->name) + (overlay->procrustes_align ? QStringLiteral(" (Procrustes-aligned)") : QString()));
    over->setMarkerShape(QScatterSeries::MarkerShapeTriangle);
    over->setMarkerSize(12);
    over->setColor(palette(1));
    over->setBorderColor(palette(1).darker(140));
    for (const auto& p : second) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      over->append(p.x, p.y);
      xr.add(p.x);
      yr.add(p.y);
    }
  }
  chart.addSeries(base);
  if (over) chart.addSeries(over);
  chart.legend()->setVisible(overlay.has_value());

  // Generous padding: labels sit beside the points and must stay inside the plot area.
  auto* x_axis = add_value_axis(chart, Qt::AlignBottom,
                                qs(options.x_label.empty() ? "Dimension 1 (arbitrary units)" : options.x_label), xr, 0.15);
  auto* y_axis = add_value_axis(chart, Qt::AlignLeft,
                                qs(options.y_label.empty() ? "Dimension 2 (arbitrary units)" : options.y_label), yr, 0.12);
  for (auto* s : chart.series()) {
    s->attachAxis(x_axis);
    s->attachAxis(y_axis);
  }

  // Distances are what an MDS map shows, so one unit is the same length on both axes: the axis with
  // more pixels per unit is extended around its centre.
  canvas.layout();
  const QRectF area = chart.plotArea();
  if (area.width() > 0 && area.height() > 0) {
    const double xspan = x_axis->max() - x_axis->min(), yspan = y_axis->max() - y_axis->min();
    const double px_per_x = area.width() / xspan, px_per_y = area.height() / yspan;
    if (px_per_x > px_per_y) {
      const double c = 0.5 * (x_axis->max() + x_axis->min()), half = 0.5 * area.width() / px_per_y;
      x_axis->setRange(c - half, c + half);
    } else {
      const double c = 0.5 * (y_axis->max() + y_axis->min()), half = 0.5 * area.height() / px_per_x;
      y_axis->setRange(c - half, c + half);
    }
    x_axis->setTickType(QValueAxis::TicksDynamic);
    y_axis->setTickType(QValueAxis::TicksDynamic);
    // One tick interval for both axes (the smaller nice step that gives >= 4 ticks on the shorter axis).
    const double shorter = std::min(x_axis->max() - x_axis->min(), y_axis->max() - y_axis->min());
    double step = std::pow(10.0, std::floor(std::log10(shorter / 4)));
    for (double m : {5.0, 2.0, 1.0})
      if (shorter / (step * m) >= 4) {
        step *= m;
        break;
      }
    for (auto* a : {x_axis, y_axis}) {
      a->setTickInterval(step);
      a->setTickAnchor(0.0);
    }
  }

  canvas.write(path, [&](QPainter& painter) {
    const QRectF plot = chart.plotArea();
    if (over) {  // thin lines joining each stimulus to its position in the second map
      painter.setPen(QPen(QColor(120, 120, 120), 1.0, Qt::SolidLine));
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(second[i].x) ||
            !std::isfinite(second[i].y))
          continue;
        painter.drawLine(chart.mapToPosition(QPointF(points[i].x, points[i].y), base),
                         chart.mapToPosition(QPointF(second[i].x, second[i].y), base));
      }
    }
    QFont font = painter.font();
    font.setPointSizeF(9.5);
    std::vector<PlacedLabel> placed;
    // Unlabelled points still enter as obstacles (empty text) so no label covers them.
    for (std::size_t i = 0; i < points.size(); ++i)
      if (std::isfinite(points[i].x) && std::isfinite(points[i].y))
        placed.push_back({chart.mapToPosition(QPointF(points[i].x, points[i].y), base),
                          labels.empty() ? QString() : qs(labels[i]), QColor(20, 20, 20), font});
    if (overlay) {
      QFont small = font;
      small.setItalic(true);
      small.setPointSizeF(8.5);
      for (std::size_t i = 0; i < second.size(); ++i)
        if (std::isfinite(second[i].x) && std::isfinite(second[i].y))
          placed.push_back({chart.mapToPosition(QPointF(second[i].x, second[i].y), base),
                            overlay->labels.empty() ? QString() : qs(overlay->labels[i]), palette(1).darker(160),
                            small});
    }
    draw_labels(painter, placed, plot, 6.5);
  });
}

}  // namespace ms::plots
