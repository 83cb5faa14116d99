// MUSHRA summary: a box plot per condition on the 0-100 scale, with mean and 95 % CI beside each box.
#include <QtCharts/QBarCategoryAxis>
#include <QtCharts/QBoxPlotSeries>
#include <QtCharts/QBoxSet>
#include <QtCharts/QLegend>

#include <algorithm>
#include <cmath>

#include "analysis/stats/box_summary.hpp"
#include "studyapp/plots/canvas.hpp"

namespace ms::plots {

using namespace detail;

void mushra_boxplot(const std::string& path, const std::vector<std::string>& conditions,
                    const std::vector<std::vector<double>>& ratings, const std::vector<double>& means,
                    const std::vector<double>& ci_low, const std::vector<double>& ci_high,
                    const PlotOptions& options) {
  check_output_path(path);
  const std::size_t n = conditions.size();
  require_size(ratings.size(), n, "mushra_boxplot: ratings");
  require_size(means.size(), n, "mushra_boxplot: means");
  require_size(ci_low.size(), n, "mushra_boxplot: ci_low");
  require_size(ci_high.size(), n, "mushra_boxplot: ci_high");
  ensure_app();

  ChartCanvas canvas(options);
  QChart& chart = canvas.chart();
  auto* boxes = new QBoxPlotSeries;
  boxes->setName(QStringLiteral("ratings"));
  boxes->setBoxWidth(0.42);
  boxes->setBrush(QColor(198, 219, 239));
  boxes->setPen(QPen(QColor(40, 70, 110), 1.4));
  std::vector<BoxSummary> stats(n);
  bool any_box = false;  // without ratings (e.g. proportions with intervals) the marks sit centred
  QStringList categories;
  for (std::size_t i = 0; i < n; ++i) {
    categories << qs(conditions[i]);
    std::vector<double> finite;
    for (double r : ratings[i])
      if (std::isfinite(r)) finite.push_back(r);
    // An empty condition still needs a set so that boxes stay aligned with their categories; a
    // degenerate box outside the axis draws nothing.
    if (finite.empty()) {
      boxes->append(new QBoxSet(-1000, -1000, -1000, -1000, -1000, qs(conditions[i])));
      continue;
    }
    stats[i] = box_summary(finite);  // Tukey's box on type-7 quartiles
    any_box = true;
    const BoxSummary& b = stats[i];
    boxes->append(new QBoxSet(b.lower_whisker, b.q1, b.median, b.q3, b.upper_whisker, qs(conditions[i])));
  }
  chart.addSeries(boxes);
  chart.legend()->setVisible(false);  // the caption below explains the symbols instead

  auto* x_axis = new QBarCategoryAxis;
  x_axis->append(categories);
  x_axis->setTitleText(qs(options.x_label.empty() ? "Condition" : options.x_label));
  QFont title_font = x_axis->titleFont();
  title_font.setPointSizeF(10);
  x_axis->setTitleFont(title_font);
  QFont label_font = x_axis->labelsFont();
  label_font.setPointSizeF(9);
  x_axis->setLabelsFont(label_font);
  // Long names would collide: tilt them when the average name is wider than its share of the width.
  double widest = 0;
  for (const auto& c : categories) widest = std::max(widest, QFontMetricsF(label_font).horizontalAdvance(c));
  if (n > 0 && widest > 0.7 * (options.width_px - 120.0) / double(n)) x_axis->setLabelsAngle(-30);
  chart.addAxis(x_axis, Qt::AlignBottom);
  auto* y_axis = add_value_axis(chart, Qt::AlignLeft,
                                qs(options.y_label.empty() ? "Rating (0 = bad, 100 = excellent)" : options.y_label),
                                Range{0, 100, false}, 0.0);
  // A little beyond 0-100 so ratings of exactly 0 or 100 do not vanish into the frame.
  y_axis->setRange(-2, 102);
  y_axis->setTickType(QValueAxis::TicksDynamic);
  y_axis->setTickAnchor(0);
  y_axis->setTickInterval(20);
  y_axis->setMinorTickCount(1);
  boxes->attachAxis(x_axis);
  boxes->attachAxis(y_axis);
  chart.setMargins(QMargins(6, 6, 12, 30));  // room for the caption

  canvas.write(path, [&](QPainter& p) {
    const QRectF plot = chart.plotArea();
    const double cat_w = n > 0 ? plot.width() / double(n) : plot.width();
    auto to_px = [&](double i, double v) {
      return QPointF(plot.left() + (i + 0.5) * cat_w, plot.bottom() - plot.height() * (std::clamp(v, 0.0, 100.0) + 2) / 104.0);
    };
    const QColor mean_color(200, 30, 30);
    p.setClipRect(plot.adjusted(-8, -8, 8, 8));
    for (std::size_t i = 0; i < n; ++i) {
      const double x_off = any_box ? 0.32 : 0.0;  // mean + CI right of the box (its half-width is 0.21)
      // Outliers: open circles on the box's axis.
      p.setPen(QPen(QColor(40, 70, 110), 1.2));
      p.setBrush(Qt::NoBrush);
      for (double v : stats[i].outliers) p.drawEllipse(to_px(double(i), v), 3.5, 3.5);
      if (std::isfinite(ci_low[i]) && std::isfinite(ci_high[i])) {
        const QPointF lo = to_px(double(i) + x_off, ci_low[i]), hi = to_px(double(i) + x_off, ci_high[i]);
        p.setPen(QPen(mean_color, 2.0));
        p.drawLine(lo, hi);
        const double cap = std::min(6.0, 0.06 * cat_w);
        p.drawLine(lo - QPointF(cap, 0), lo + QPointF(cap, 0));
        p.drawLine(hi - QPointF(cap, 0), hi + QPointF(cap, 0));
      }
      if (std::isfinite(means[i])) {
        const QPointF c = to_px(double(i) + x_off, means[i]);
        const double r = 5.5;
        p.setPen(QPen(mean_color.darker(130), 1));
        p.setBrush(mean_color);
        p.drawPolygon(QPolygonF({c + QPointF(0, -r), c + QPointF(r, 0), c + QPointF(0, r), c + QPointF(-r, 0)}));
      }
    }
    p.setClipping(false);
    // Caption: what the symbols mean.
    QFont f = p.font();
    f.setPointSizeF(8.5);
    p.setFont(f);
    p.setPen(QColor(60, 60, 60));
    p.drawText(QRectF(0, options.height_px - 24, options.width_px, 20), Qt::AlignCenter,
               any_box ? QString::fromUtf8("Box: median and quartiles; whiskers: furthest rating within 1.5 IQR; "
                                           "○ outlier; ◆ mean with 95 % confidence interval")
                       : QString::fromUtf8("◆ estimate with its 95 % confidence interval"));
  });
}

}  // namespace ms::plots
