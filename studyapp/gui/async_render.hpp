// Re-synthesis off the GUI thread (adjust sliders, staircase levels): StimulusCache::samples_with runs
// on the global QThreadPool and the result comes back on the GUI thread, dropped if `context` is gone.
#pragma once
#include <QObject>

#include <functional>
#include <string>
#include <vector>

#include "studyapp/core/stimulus_cache.hpp"

namespace ms::gui {

// done(samples, render_ms, error) runs on the GUI thread; error is "" on success.
void render_async(StimulusCache& cache, const std::string& name, std::vector<std::string> overrides, QObject* context,
                  std::function<void(Samples, double, std::string)> done);

// "key=value" with the value written so that it reads back exactly (%.17g).
std::string override_text(const std::string& key, double value);

}  // namespace ms::gui
