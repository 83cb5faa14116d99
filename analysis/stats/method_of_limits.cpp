#include "analysis/stats/method_of_limits.hpp"

#include <stdexcept>
#include <utility>

#include "analysis/stats/row_groups.hpp"

namespace ms {

LimitsThreshold descending_limits_threshold(const std::vector<double>& levels, const std::vector<bool>& different) {
  if (levels.size() != different.size()) throw std::invalid_argument("levels and answers differ in length");
  for (std::size_t i = 1; i < levels.size(); ++i)
    if (!(levels[i] < levels[i - 1]))
      throw std::invalid_argument("trial " + std::to_string(i + 1) + ": level " + std::to_string(levels[i]) +
                                  " does not fall below the previous one");
  LimitsThreshold t;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (!different[i]) continue;
    t.first_different = i;
    if (i > 0) t.threshold = levels[i - 1];
    return t;
  }
  if (!levels.empty()) {
    t.threshold = levels.back();
    t.censored = true;
  }
  return t;
}

}  // namespace ms

namespace ms {

std::vector<LimitsSeries> limits_series_from_table(const TidyCsv& table, const LimitsColumns& columns) {
  const std::size_t cl = table.column(columns.level), cr = table.column(columns.response);
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  std::vector<LimitsSeries> out;
  for (const auto& [name, rows] : group_rows(table, columns.track)) {
    LimitsSeries s{name, {}, {}};
    for (std::size_t i = 0; i < rows.size(); ++i) {
      s.levels.push_back(table.number(rows[i], cl));
      if (i > 0 && !(s.levels[i] < s.levels[i - 1]))
        throw InputError(table.where(rows[i], cl), "column '" + columns.level + "': level " +
                                                       table.cell(rows[i], cl) +
                                                       " does not fall below the previous trial of its series");
      s.different.push_back(table.cell(rows[i], cr) == columns.different);
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace ms
