// Headless Qt set-up, PNG/SVG writing and the chart canvas shared by every plot kind.
#include "studyapp/plots/canvas.hpp"

#include <QApplication>
#include <QBuffer>
#include <QImage>
#include <QSvgGenerator>
#include <QtCharts/QLegend>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "synthesis/atomic_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms::plots {

bool check_output_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".png") return false;
  if (ext == ".svg") return true;
  throw InputError(SourceLocation{path, 0, 0}, "unknown picture format '" + ext + "' (expected .png or .svg)");
}

namespace detail {

namespace {

// Qt's platform plugins chat on stderr (e.g. "XDG_RUNTIME_DIR not set"); a command's stderr is for
// its own one-line errors, so only real warnings from our own use get through.
void quiet_message_handler(QtMsgType type, const QMessageLogContext&, const QString& message) {
  if (type == QtDebugMsg || type == QtInfoMsg) return;
  if (message.contains(QLatin1String("XDG_RUNTIME_DIR")) || message.contains(QLatin1String("propagateSizeHints")))
    return;
  std::fprintf(stderr, "qt: %s\n", message.toLocal8Bit().constData());
}

}  // namespace

void ensure_app() {
  if (QCoreApplication::instance() != nullptr) {
    if (qobject_cast<QGuiApplication*>(QCoreApplication::instance()) == nullptr)
      throw std::logic_error("ms::plots needs a QGuiApplication (fonts), not a QCoreApplication");
    return;
  }
  const bool has_display = std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr;
  if (!has_display && !qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  qInstallMessageHandler(quiet_message_handler);
  // QApplication keeps references to argc/argv for its whole life, which is the program's.
  static int argc = 1;
  static char name[] = "modalstudy";
  static char* argv[] = {name, nullptr};
  static QApplication* app = new QApplication(argc, argv);  // never deleted: lives until exit
  (void)app;
}

QString qs(const std::string& s) { return QString::fromStdString(s); }

void require_size(std::size_t n, std::size_t expected, const char* what) {
  if (n != expected)
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(n) + " entries, expected " +
                                std::to_string(expected));
}

QColor palette(std::size_t i) {
  static const std::array<const char*, 10> colors = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                                     "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return QColor(colors[i % colors.size()]);
}

void write_picture(const std::string& path, const PlotOptions& options,
                   const std::function<void(QPainter&)>& paint) {
  const bool svg = check_output_path(path);
  if (options.width_px < 16 || options.height_px < 16 || options.width_px > 20000 || options.height_px > 20000)
    throw std::invalid_argument("plot size must be 16..20000 pixels per side");
  const QSize size(options.width_px, options.height_px);
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  // Both outputs at the screen's logical DPI, so text laid out by the chart keeps its measured size.
  const int dpi = 96;
  if (svg) {
    QSvgGenerator generator;
    generator.setOutputDevice(&buffer);
    generator.setSize(size);
    generator.setViewBox(QRect(QPoint(0, 0), size));
    generator.setResolution(dpi);
    // QSvgGenerator 6.4 writes <title> verbatim: escape it, or a title with '&' or '<' breaks the XML.
    generator.setTitle(options.title.empty() ? QStringLiteral("ModalStudy plot") : qs(options.title).toHtmlEscaped());
    generator.setDescription(QStringLiteral("Made by ModalStudy (ms::plots)"));
    QPainter painter(&generator);
    painter.setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing);
    painter.fillRect(QRect(QPoint(0, 0), size), Qt::white);
    paint(painter);
    painter.end();
  } else {
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    const int dots_per_meter = int(dpi / 0.0254 + 0.5);
    image.setDotsPerMeterX(dots_per_meter);
    image.setDotsPerMeterY(dots_per_meter);
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing | QPainter::SmoothPixmapTransform);
    paint(painter);
    painter.end();
    if (!image.save(&buffer, "PNG")) throw std::runtime_error("PNG encoding failed for " + path);
  }
  buffer.close();
  write_file_atomically(path, std::string(bytes.constData(), std::size_t(bytes.size())));
}

ChartCanvas::ChartCanvas(const PlotOptions& options) : options_(options), chart_(new QChart) {
  scene_.addItem(chart_);
  chart_->setAnimationOptions(QChart::NoAnimation);
  chart_->setBackgroundRoundness(0);
  chart_->setDropShadowEnabled(false);
  chart_->setBackgroundBrush(Qt::white);
  chart_->setMargins(QMargins(6, 6, 12, 6));
  if (!options.title.empty()) {
    QFont f = chart_->titleFont();
    f.setPointSizeF(std::max(9.0, 13.0 * std::min(options.width_px, options.height_px) / 600.0));
    f.setBold(true);
    chart_->setTitleFont(f);
    chart_->setTitle(qs(options.title));
  }
  chart_->legend()->setAlignment(Qt::AlignBottom);
}

void ChartCanvas::layout() {
  chart_->setGeometry(QRectF(0, 0, options_.width_px, options_.height_px));
  // QGraphicsWidget layouts run on posted LayoutRequest events; deliver them now.
  for (int i = 0; i < 3; ++i) {
    QCoreApplication::sendPostedEvents();
    QCoreApplication::processEvents();
  }
}

void ChartCanvas::write(const std::string& path, const std::function<void(QPainter&)>& annotate) {
  layout();
  write_picture(path, options_, [&](QPainter& painter) {
    const QRectF rect(0, 0, options_.width_px, options_.height_px);
    scene_.render(&painter, rect, rect);
    if (annotate) {
      painter.save();
      annotate(painter);
      painter.restore();
    }
  });
}

void Range::add(double v, bool positive_only) {
  if (!std::isfinite(v) || (positive_only && v <= 0)) return;
  if (empty) {
    lo = hi = v;
    empty = false;
  } else {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
}

namespace {

void style_axis(QAbstractAxis& axis, const QString& title) {
  axis.setTitleText(title);
  QFont f = axis.titleFont();
  f.setPointSizeF(10);
  f.setBold(false);
  axis.setTitleFont(f);
  QFont l = axis.labelsFont();
  l.setPointSizeF(9);
  axis.setLabelsFont(l);
  axis.setGridLineColor(QColor(225, 225, 225));
  axis.setMinorGridLineColor(QColor(242, 242, 242));
}

}  // namespace

QValueAxis* add_value_axis(QChart& chart, Qt::Alignment side, const QString& title, Range range,
                           double pad_fraction) {
  if (range.empty) range = Range{0, 1, false};
  double span = range.hi - range.lo;
  if (span <= 0) span = std::max(1.0, std::abs(range.hi));
  double lo = range.lo - pad_fraction * span, hi = range.hi + pad_fraction * span;
  // Padding must not invent negative values for non-negative data (ratings, counts), nor vice versa.
  if (range.lo >= 0 && lo < 0) lo = 0;
  if (range.hi <= 0 && hi > 0) hi = 0;
  auto* axis = new QValueAxis;
  style_axis(*axis, title);
  axis->setRange(lo, hi);
  axis->applyNiceNumbers();  // round ticks (1, 2, 5 x 10^k)
  axis->setLabelFormat("%g");
  chart.addAxis(axis, side);
  return axis;
}

QLogValueAxis* add_log_axis(QChart& chart, Qt::Alignment side, const QString& title, Range range) {
  if (range.empty) range = Range{1, 10, false};
  // Ends at 1, 2 or 5 x 10^k just outside the data; whole decades when that would leave fewer than
  // two labelled powers of 10 (QLogValueAxis labels only those).
  auto round_down = [](double v) {
    const double decade = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {5.0, 2.0, 1.0})
      if (m * decade <= v) return m * decade;
    return decade;
  };
  auto round_up = [](double v) {
    const double decade = std::pow(10.0, std::floor(std::log10(v)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
      if (m * decade >= v) return m * decade;
    return 10 * decade;
  };
  double lo = round_down(range.lo / 1.1), hi = round_up(range.hi * 1.1);
  const int powers = int(std::floor(std::log10(hi) + 1e-9) - std::ceil(std::log10(lo) - 1e-9)) + 1;
  if (powers < 2) {
    lo = std::pow(10.0, std::floor(std::log10(range.lo)));
    hi = std::pow(10.0, std::ceil(std::log10(range.hi)));
    if (hi <= lo * 1.000001) hi = lo * 10;
  }
  auto* axis = new QLogValueAxis;
  style_axis(*axis, title);
  axis->setBase(10);
  axis->setRange(lo, hi);
  axis->setLabelFormat("%g");
  axis->setMinorTickCount(8);  // 2..9 within each decade
  chart.addAxis(axis, side);
  return axis;
}

void draw_labels(QPainter& painter, const std::vector<PlacedLabel>& labels, const QRectF& bounds,
                 double marker_radius_px) {
  std::vector<QRectF> taken;
  for (const auto& l : labels) {
    const double r = marker_radius_px;
    taken.emplace_back(l.anchor.x() - r, l.anchor.y() - r, 2 * r, 2 * r);
  }
  auto overlap = [&](const QRectF& box) {
    double area = 0;
    for (const auto& t : taken) {
      const QRectF i = box.intersected(t);
      if (!i.isEmpty()) area += i.width() * i.height();
    }
    const QRectF inside = box.intersected(bounds);
    area += box.width() * box.height() - (inside.isEmpty() ? 0.0 : inside.width() * inside.height());
    return area;
  };
  for (const auto& l : labels) {
    if (l.text.isEmpty()) continue;
    painter.setFont(l.font);
    const QFontMetricsF fm(l.font);
    const double w = fm.horizontalAdvance(l.text) + 2, h = fm.height();
    const double gap = marker_radius_px + 2;
    const double x = l.anchor.x(), y = l.anchor.y();
    // Right, left, above, below, then the diagonals: right of the point reads most naturally.
    const std::array<QRectF, 8> candidates = {
        QRectF(x + gap, y - h / 2, w, h),         QRectF(x - gap - w, y - h / 2, w, h),
        QRectF(x - w / 2, y - gap - h, w, h),     QRectF(x - w / 2, y + gap, w, h),
        QRectF(x + gap * 0.7, y - gap * 0.7 - h, w, h), QRectF(x - gap * 0.7 - w, y - gap * 0.7 - h, w, h),
        QRectF(x + gap * 0.7, y + gap * 0.7, w, h),     QRectF(x - gap * 0.7 - w, y + gap * 0.7, w, h)};
    QRectF best = candidates[0];
    double best_overlap = std::numeric_limits<double>::infinity();
    for (const auto& c : candidates) {
      const double o = overlap(c);
      if (o < best_overlap) {
        best_overlap = o;
        best = c;
      }
      if (o == 0) break;
    }
    taken.push_back(best);
    painter.setPen(l.color);
    painter.drawText(best, Qt::AlignCenter, l.text);
  }
}

}  // namespace detail

}  // namespace ms::plots
