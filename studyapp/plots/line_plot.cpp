// Line plot: named series of (x, y) points joined by lines with markers, optional log-x axis.
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>

#include <cmath>

#include "studyapp/plots/canvas.hpp"

namespace ms::plots {

using namespace detail;

void line_plot(const std::string& path, const std::vector<Series>& series, const PlotOptions& options, bool log_x) {
  check_output_path(path);
  ensure_app();
  ChartCanvas canvas(options);
  QChart& chart = canvas.chart();
  Range xr, yr;
  for (std::size_t k = 0; k < series.size(); ++k) {
    auto* line = new QLineSeries;
    line->setName(qs(series[k].name));
    line->setPen(QPen(palette(k), 2.2));
    line->setPointsVisible(true);
    line->setMarkerSize(7);
    for (const auto& p : series[k].points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || (log_x && p.x <= 0)) continue;
      line->append(p.x, p.y);
      xr.add(p.x);
      yr.add(p.y);
    }
    chart.addSeries(line);
  }
  chart.legend()->setVisible(series.size() > 1 || (series.size() == 1 && !series[0].name.empty()));
  const QString x_title = qs(options.x_label.empty() ? "x" : options.x_label);
  QAbstractAxis* x_axis = nullptr;
  if (log_x)
    x_axis = add_log_axis(chart, Qt::AlignBottom, x_title, xr);
  else
    x_axis = add_value_axis(chart, Qt::AlignBottom, x_title, xr, 0.03);
  auto* y_axis = add_value_axis(chart, Qt::AlignLeft, qs(options.y_label.empty() ? "y" : options.y_label), yr, 0.08);
  for (auto* s : chart.series()) {
    s->attachAxis(x_axis);
    s->attachAxis(y_axis);
  }
  canvas.write(path);
}

}  // namespace ms::plots
