// Damping features (lambda, c = 2d) as a scatter with fitted damping-law curves, log-log by default.
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>

#include <cmath>

#include "studyapp/plots/canvas.hpp"

namespace ms::plots {

using namespace detail;

void damping_scatter(const std::string& path, const std::vector<double>& lambda_rad2_s2,
                     const std::vector<double>& c_per_s, const std::vector<Series>& fitted_laws,
                     const PlotOptions& options, bool log_log) {
  check_output_path(path);
  require_size(c_per_s.size(), lambda_rad2_s2.size(), "damping_scatter: c_per_s");
  ensure_app();
  ChartCanvas canvas(options);
  QChart& chart = canvas.chart();
  Range xr, yr;
  auto* points = new QScatterSeries;
  points->setName(QStringLiteral("features (%1)").arg(lambda_rad2_s2.size()));
  points->setMarkerSize(6);
  // Semi-transparent so dense clusters of strikes read as density.
  QColor fill(90, 90, 90, 110);
  points->setColor(fill);
  points->setBorderColor(QColor(60, 60, 60, 160));
  for (std::size_t i = 0; i < lambda_rad2_s2.size(); ++i) {
    const double x = lambda_rad2_s2[i], y = c_per_s[i];
    if (!std::isfinite(x) || !std::isfinite(y) || (log_log && (x <= 0 || y <= 0))) continue;
    points->append(x, y);
    xr.add(x);
    yr.add(y);
  }
  chart.addSeries(points);
  for (std::size_t k = 0; k < fitted_laws.size(); ++k) {
    auto* curve = new QLineSeries;
    curve->setName(qs(fitted_laws[k].name));
    QPen pen(palette(k), 2.4);
    if (k % 3 == 1) pen.setStyle(Qt::DashLine);  // overlapping fits stay distinguishable
    if (k % 3 == 2) pen.setStyle(Qt::DashDotLine);
    curve->setPen(pen);
    for (const auto& p : fitted_laws[k].points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || (log_log && (p.x <= 0 || p.y <= 0))) continue;
      curve->append(p.x, p.y);
      // Curves extend the axes only over the data's lambda range, so a wild fit cannot squash the data.
      if (xr.empty || (p.x >= xr.lo && p.x <= xr.hi)) yr.add(p.y, log_log);
    }
    chart.addSeries(curve);
  }
  const QString x_title =
      qs(options.x_label.empty() ? "λ = ω² = ω_d² + d²  [(rad/s)²]" : options.x_label);
  const QString y_title = qs(options.y_label.empty() ? "c = 2d  [1/s]" : options.y_label);
  QAbstractAxis* x_axis = nullptr;
  QAbstractAxis* y_axis = nullptr;
  if (log_log) {
    x_axis = add_log_axis(chart, Qt::AlignBottom, x_title, xr);
    y_axis = add_log_axis(chart, Qt::AlignLeft, y_title, yr);
  } else {
    x_axis = add_value_axis(chart, Qt::AlignBottom, x_title, xr);
    y_axis = add_value_axis(chart, Qt::AlignLeft, y_title, yr);
    static_cast<QValueAxis*>(x_axis)->setLabelFormat("%.3g");
  }
  for (auto* s : chart.series()) {
    s->attachAxis(x_axis);
    s->attachAxis(y_axis);
  }
  canvas.write(path);
}

}  // namespace ms::plots
