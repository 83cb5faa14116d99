// Internal to modalstudy_plots: the frame both time x band pictures share (the residual map and the
// loudness image) - cells painted by a colour function, band ticks on the left, time ticks below, and
// a colour bar with its unit on the right.
#pragma once
#include <QColor>

#include <functional>
#include <string>
#include <vector>

#include "studyapp/plots/plots.hpp"

namespace ms::plots::detail {

struct TimeBandMap {
  const std::vector<std::vector<double>>* cells = nullptr;  // [band][frame]; non-finite cells are grey
  double duration_s = 0;                                    // time spanned by the frames
  std::function<QColor(double)> colour;                     // of a finite cell value
  // Band-axis ticks: label text at a position measured in bands from the bottom edge.
  std::vector<std::pair<double, std::string>> band_ticks;
  std::string band_label;                                   // y-axis title when options give none
  double bar_lo = 0, bar_hi = 1;                            // colour bar span
  std::string bar_unit;                                     // " dB", " sone"
};

// Checks the matrix, then paints the map and writes PNG or SVG atomically to `path`.
void write_time_band_map(const std::string& path, const TimeBandMap& map, const PlotOptions& options,
                         const char* what);

}  // namespace ms::plots::detail
