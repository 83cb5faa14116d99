// render_async: one pooled task per request; the caller coalesces requests (see adjust_view.cpp).
#include "studyapp/gui/async_render.hpp"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QPointer>
#include <QThreadPool>

#include <cstdio>

namespace ms::gui {

void render_async(StimulusCache& cache, const std::string& name, std::vector<std::string> overrides, QObject* context,
                  std::function<void(Samples, double, std::string)> done) {
  QPointer<QObject> guard(context);
  QThreadPool::globalInstance()->start([&cache, name, overrides = std::move(overrides), guard, done = std::move(done)] {
    QElapsedTimer clock;
    clock.start();
    Samples samples;
    std::string error;
    try {
      samples = cache.samples_with(name, overrides);
    } catch (const std::exception& e) {
      error = e.what();
    }
    const double render_ms = static_cast<double>(clock.nsecsElapsed()) * 1e-6;
    QMetaObject::invokeMethod(QCoreApplication::instance(), [guard, done, samples, render_ms, error] {
      if (guard) done(samples, render_ms, error);
    }, Qt::QueuedConnection);
  });
}

std::string override_text(const std::string& key, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", value);
  return key + "=" + buf;
}

}  // namespace ms::gui
