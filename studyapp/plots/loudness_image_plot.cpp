// Loudness image: a time x Bark matrix in sone painted as a heat map (white -> dark red for a
// loudness image, blue/white/red for a difference of two), with a colour bar in sone.
#include <algorithm>
#include <cmath>

#include "studyapp/plots/time_band_map.hpp"

namespace ms::plots {

namespace {

QColor mix(const double (&from)[3], const double (&to)[3], double u) {
  auto c = [&](int k) { return int(std::lround(from[k] + u * (to[k] - from[k]))); };
  return QColor(c(0), c(1), c(2));
}

// Sequential for 0..limit (a loudness), diverging for -limit..limit (a difference).
QColor colour(double v, double limit, bool difference) {
  static const double white[3] = {255, 255, 255}, blue[3] = {33, 102, 172}, red[3] = {178, 24, 43},
                      dark[3] = {103, 0, 13};
  if (difference) {
    const double t = std::clamp(v / limit, -1.0, 1.0);
    return mix(white, t < 0 ? blue : red, std::abs(t));
  }
  return mix(white, dark, std::clamp(v / limit, 0.0, 1.0));
}

}  // namespace

void loudness_image(const std::string& path, const std::vector<std::vector<double>>& sone_by_band, double hop_s,
                    double band_bark, bool difference, const PlotOptions& options) {
  double limit = 0.0;
  for (const auto& row : sone_by_band)
    for (double v : row)
      if (std::isfinite(v)) limit = std::max(limit, std::abs(v));
  if (!(limit > 0.0)) limit = 1.0;
  detail::TimeBandMap map;
  map.cells = &sone_by_band;
  map.duration_s = sone_by_band.empty() ? 0.0 : hop_s * double(sone_by_band.front().size());
  map.colour = [=](double v) { return colour(v, limit, difference); };
  const double top_bark = double(sone_by_band.size()) * band_bark;
  for (double z = 0.0; z <= top_bark + 1e-9; z += 5.0)  // every 5 Bark
    map.band_ticks.emplace_back(z / band_bark, std::to_string(int(z)));
  map.band_label = "critical-band rate [Bark]";
  map.bar_lo = difference ? -limit : 0.0;
  map.bar_hi = limit;
  map.bar_unit = " sone";
  detail::write_time_band_map(path, map, options, "loudness_image");
}

}  // namespace ms::plots
