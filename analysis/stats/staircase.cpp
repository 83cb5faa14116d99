#include "analysis/stats/staircase.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "analysis/stats/row_groups.hpp"

namespace ms {

std::size_t staircase_default_skip(std::size_t reversals) { return reversals > 4 ? 2 : 0; }

StaircaseThreshold staircase_threshold(const std::vector<double>& levels, std::optional<double> next_level,
                                       const StaircaseOptions& options) {
  std::vector<double> path = levels;
  if (next_level) path.push_back(*next_level);
  StaircaseThreshold out;
  int direction = 0;  // +1 rising, -1 falling, 0 not yet moved
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double step = path[i] - path[i - 1];
    if (step == 0) continue;
    const int d = step > 0 ? 1 : -1;
    // The level before this step is where the track turned.
    if (direction != 0 && d != direction) {
      out.reversal_trials.push_back(i - 1);
      out.reversal_levels.push_back(path[i - 1]);
    }
    direction = d;
  }
  const std::size_t n = out.reversal_levels.size();
  out.used = options.last_k ? std::min(*options.last_k, n) : n - staircase_default_skip(n);
  if (out.used == 0) return out;
  double sum = 0;
  for (std::size_t i = n - out.used; i < n; ++i)
    sum += options.log_scale ? std::log(out.reversal_levels[i]) : out.reversal_levels[i];
  const double mean = sum / double(out.used);
  out.threshold = options.log_scale ? std::exp(mean) : mean;
  if (out.used >= 2) {
    double ss = 0;  // two-pass: no cancellation for levels far from zero
    for (std::size_t i = n - out.used; i < n; ++i) {
      const double v = options.log_scale ? std::log(out.reversal_levels[i]) : out.reversal_levels[i];
      ss += (v - mean) * (v - mean);
    }
    out.sd = std::sqrt(ss / double(out.used - 1));
  }
  return out;
}

}  // namespace ms

namespace ms {

StaircaseTracks staircase_tracks_from_table(const TidyCsv& table, const StaircaseColumns& columns, bool log_scale) {
  const std::size_t cl = table.column(columns.level);
  const std::size_t ct = columns.trial.empty() ? 0 : table.column(columns.trial);
  StaircaseTracks out;
  out.has_next_level = !columns.next_level.empty() && table.has_column(columns.next_level);
  const std::size_t cn = out.has_next_level ? table.column(columns.next_level) : 0;
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  for (auto [name, rows] : group_rows(table, columns.track)) {
    if (!columns.trial.empty()) {
      std::vector<std::pair<double, std::size_t>> order;
      for (std::size_t r : rows) order.push_back({table.number(r, ct), r});
      std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = order[i].second;
    }
    StaircaseTrackLevels track{name, {}, std::nullopt};
    for (std::size_t r : rows) {
      track.levels.push_back(table.number(r, cl));
      if (log_scale && !(track.levels.back() > 0))
        throw InputError(table.where(r, cl), "column '" + columns.level + "': --log needs levels above 0");
    }
    if (out.has_next_level) track.next_level = table.number(rows.back(), cn);
    out.tracks.push_back(std::move(track));
  }
  return out;
}

}  // namespace ms
