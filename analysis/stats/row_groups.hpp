// Rows of a tidy table grouped by the values of some columns (a listener, a track, a condition):
// the group name joins the values with '/', "" when no column is given; groups and their rows keep
// the order of first appearance in the file.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

using RowGroups = std::vector<std::pair<std::string, std::vector<std::size_t>>>;

// InputError "missing column" when a column of `by` is absent.
RowGroups group_rows(const TidyCsv& table, const std::vector<std::string>& by);

}  // namespace ms
