// Marks of material changes per value of a sweep; see change_points.hpp.
#include "analysis/stats/change_points.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "analysis/stats/row_groups.hpp"

namespace ms {

std::vector<ChangepointGroup> change_points_from_table(const TidyCsv& table, const ChangepointColumns& columns,
                                                       std::size_t top) {
  const std::size_t cv = table.column(columns.value), cm = table.column(columns.marked);
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  std::vector<ChangepointGroup> out;
  for (const auto& [name, rows] : group_rows(table, columns.by)) {
    std::map<double, std::size_t> marks;  // value -> marks, rising
    std::map<std::string, std::set<double>> sweeps;  // sweep -> values it played
    const TidyCsv part = table.keep_rows(rows);
    for (const auto& [sweep, sweep_rows] : group_rows(part, columns.sweep)) {
      std::set<double>& played = sweeps[sweep];
      for (std::size_t r : sweep_rows) {
        const double v = part.number(r, cv);
        if (!played.insert(v).second)
          throw InputError(part.where(r, cv), "column '" + columns.value + "': sweep '" + sweep + "' plays " +
                                                  part.cell(r, cv) + " twice");
        const std::string& m = part.cell(r, cm);
        if (m != "0" && m != "1")
          throw InputError(part.where(r, cm), "column '" + columns.marked + "': expected 1 (marked) or 0, got '" + m + "'");
        marks[v] += m == "1" ? 1 : 0;
      }
    }
    ChangepointGroup g;
    g.name = name;
    g.sweeps = sweeps.size();
    for (const auto& [v, n] : marks) {
      g.values.push_back(v);
      g.marks.push_back(n);
    }
    std::vector<std::size_t> order(g.values.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return g.marks[a] > g.marks[b]; });
    for (std::size_t k = 0; k < order.size(); ++k) {
      const std::size_t i = order[k];
      if (g.marks[i] == 0) break;
      if (k >= top && (top == 0 || g.marks[i] < g.marks[order[top - 1]])) break;
      g.most_chosen.push_back(g.values[i]);
    }
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace ms
