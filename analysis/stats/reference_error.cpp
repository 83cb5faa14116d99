#include "analysis/stats/reference_error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace ms {

namespace {

struct Mean {
  double sum = 0.0;
  std::size_t n = 0;
  std::size_t first_row = 0;
  double value() const { return sum / double(n); }
};

}  // namespace

RmData reference_error_design(const TidyCsv& table, const ReferenceErrorColumns& columns) {
  const std::size_t dv = table.column(columns.dv), subject = table.column(columns.subject),
                    dataset = table.column(columns.dataset);
  std::vector<std::size_t> match;
  for (const std::string& m : columns.match) match.push_back(table.column(m));
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");

  RmData out;
  out.within.push_back({columns.dataset, {}});
  std::vector<std::string>& levels = out.within.front().levels;
  // (subject, dataset, sound) -> the mean rating; subjects and datasets in order of first appearance.
  std::map<std::tuple<std::string, std::string, std::string>, Mean> rating;
  bool any_reference = false;
  for (std::size_t r = 0; r < table.rows(); ++r) {
    const std::string& s = table.cell(r, subject);
    const std::string& d = table.cell(r, dataset);
    std::string sound;
    for (std::size_t c : match) sound += table.cell(r, c) + '\x1f';
    Mean& m = rating[{s, d, sound}];
    if (m.n == 0) m.first_row = r;
    m.sum += table.number(r, dv);
    ++m.n;
    if (d == columns.reference) any_reference = true;
    else if (std::find(levels.begin(), levels.end(), d) == levels.end()) levels.push_back(d);
    if (std::find(out.subjects.begin(), out.subjects.end(), s) == out.subjects.end()) out.subjects.push_back(s);
  }
  if (!any_reference)
    throw InputError(SourceLocation{table.file(), 0, 0}, "no row of the reference dataset '" + columns.reference +
                                                             "' in column '" + columns.dataset + "'");
  if (levels.size() < 2)
    throw InputError(SourceLocation{table.file(), 0, 0},
                     "needs at least two datasets beside the reference '" + columns.reference + "', found " +
                         std::to_string(levels.size()));
  if (out.subjects.size() < 2)
    throw InputError(SourceLocation{table.file(), 0, 0}, "needs at least two subjects, found " +
                                                             std::to_string(out.subjects.size()));

  // Every sound a subject rated in a dataset has the subject's reference rating, and the other way round.
  std::map<std::pair<std::string, std::string>, Mean> error;  // (subject, dataset) -> mean |x - ref|
  for (const auto& [key, m] : rating) {
    const auto& [s, d, sound] = key;
    if (d == columns.reference) {
      for (const std::string& level : levels)
        if (!rating.count({s, level, sound}))
          throw InputError(table.where(m.first_row, dataset),
                           "subject '" + s + "' rated this sound in '" + columns.reference + "' but not in '" +
                               level + "'");
      continue;
    }
    const auto ref = rating.find({s, columns.reference, sound});
    if (ref == rating.end())
      throw InputError(table.where(m.first_row, dataset), "subject '" + s + "' rated this sound in '" + d +
                                                              "' but not in the reference '" + columns.reference + "'");
    Mean& e = error[{s, d}];
    e.sum += std::abs(m.value() - ref->second.value());
    ++e.n;
  }
  out.cell_mean.resize(Eigen::Index(out.subjects.size()), Eigen::Index(levels.size()));
  out.between_level.resize(Eigen::Index(out.subjects.size()), 0);
  for (std::size_t i = 0; i < out.subjects.size(); ++i)
    for (std::size_t j = 0; j < levels.size(); ++j) {
      const auto e = error.find({out.subjects[i], levels[j]});
      if (e == error.end())
        throw InputError(SourceLocation{table.file(), 0, 0},
                         "subject '" + out.subjects[i] + "' has no rating in dataset '" + levels[j] + "'");
      out.cell_mean(Eigen::Index(i), Eigen::Index(j)) = e->second.value();
    }
  return out;
}

}  // namespace ms
