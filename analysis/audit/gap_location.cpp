// Worst bands and frames of a gap, and the strike-averaged residual map; see gap_location.hpp.
#include "analysis/audit/gap_location.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace ms::audit {

std::vector<std::size_t> worst_bands(const GapLocation& location, std::size_t k) {
  std::vector<std::size_t> bands(location.band_gap_db.size());
  std::iota(bands.begin(), bands.end(), std::size_t{0});
  std::stable_sort(bands.begin(), bands.end(),
                   [&](std::size_t a, std::size_t b) { return location.band_gap_db[a] > location.band_gap_db[b]; });
  bands.resize(std::min(k, bands.size()));
  return bands;
}

std::size_t worst_frame(const GapLocation& location) {
  std::size_t worst = 0;
  for (std::size_t f = 0; f < location.time_gap_db.size(); ++f)
    if (location.time_gap_db[f] > location.time_gap_db[worst]) worst = f;
  return worst;
}

std::vector<std::vector<double>> mean_gap_map(const std::vector<GapMap>& maps) {
  if (maps.empty()) return {};
  const std::size_t bands = maps.front().bands, frames = maps.front().frames;
  std::vector<std::vector<double>> out(bands, std::vector<double>(frames, std::numeric_limits<double>::quiet_NaN()));
  for (std::size_t b = 0; b < bands; ++b)
    for (std::size_t f = 0; f < frames; ++f) {
      double sum = 0.0;
      int n = 0;
      for (const auto& m : maps)
        if (!std::isnan(m.diff_db[f * bands + b])) {
          sum += m.diff_db[f * bands + b];
          ++n;
        }
      if (n > 0) out[b][f] = sum / n;
    }
  return out;
}

}  // namespace ms::audit
