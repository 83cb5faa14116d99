// group_rows: one pass over the table, groups indexed by their joined key.
#include "analysis/stats/row_groups.hpp"

#include <map>

namespace ms {

RowGroups group_rows(const TidyCsv& table, const std::vector<std::string>& by) {
  std::vector<std::size_t> cols;
  for (const auto& b : by) cols.push_back(table.column(b));
  RowGroups groups;
  std::map<std::string, std::size_t> index;
  for (std::size_t r = 0; r < table.rows(); ++r) {
    std::string key;
    for (std::size_t c : cols) key += (key.empty() ? "" : "/") + table.cell(r, c);
    auto [it, added] = index.try_emplace(key, groups.size());
    if (added) groups.push_back({key, {}});
    groups[it->second].second.push_back(r);
  }
  return groups;
}

}  // namespace ms
