// Residual map: a time x Bark-band matrix of dB differences (model - measured) painted as a diverging
// heat map (blue: model too quiet, red: model too loud, grey: below the floor in both), with a colour bar.
#include <algorithm>
#include <cmath>

#include "studyapp/plots/time_band_map.hpp"

namespace ms::plots {

namespace {

QColor diverging(double v, double limit) {
  const double t = std::clamp(v / limit, -1.0, 1.0);
  const double blue[3] = {33, 102, 172}, white[3] = {247, 247, 247}, red[3] = {178, 24, 43};
  const double* end = t < 0 ? blue : red;
  const double u = std::abs(t);
  auto mix = [&](int c) { return int(std::lround(white[c] + u * (end[c] - white[c]))); };
  return QColor(mix(0), mix(1), mix(2));
}

}  // namespace

void residual_map(const std::string& path, const std::vector<std::vector<double>>& diff_db_by_band,
                  double duration_s, double limit_db, const PlotOptions& options) {
  detail::TimeBandMap map;
  map.cells = &diff_db_by_band;
  map.duration_s = duration_s;
  map.colour = [=](double v) { return diverging(v, limit_db); };
  for (std::size_t b = 0; b < diff_db_by_band.size(); b += 4)  // every 4th band, at its centre
    map.band_ticks.emplace_back(double(b) + 0.5, std::to_string(b));
  map.band_label = "Bark band";
  map.bar_lo = -limit_db;
  map.bar_hi = limit_db;
  map.bar_unit = " dB";
  detail::write_time_band_map(path, map, options, "residual_map");
}

}  // namespace ms::plots
