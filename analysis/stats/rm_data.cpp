#include "analysis/stats/rm_data.hpp"

#include <unordered_map>

namespace ms {

std::size_t RmData::cells() const {
  std::size_t n = 1;
  for (const auto& f : within) n *= f.levels.size();
  return n;
}

namespace {

// Level index of a value, adding it on first sight.
int level_of(RmFactor& f, std::unordered_map<std::string, int>& index, const std::string& value) {
  auto [it, added] = index.try_emplace(value, int(f.levels.size()));
  if (added) f.levels.push_back(value);
  return it->second;
}

std::string cell_label(const std::vector<RmFactor>& within, std::size_t cell) {
  std::string s;
  std::size_t stride = 1;
  for (const auto& f : within) stride *= f.levels.size();
  for (const auto& f : within) {
    stride /= f.levels.size();
    const std::size_t level = (cell / stride) % f.levels.size();
    s += (s.empty() ? "" : ", ") + f.name + "=" + f.levels[level];
  }
  return s;
}

}  // namespace

RmData rm_data_from_table(const TidyCsv& table, const RmColumns& columns, std::vector<std::string>& notices) {
  // Resolve every column first so a missing one is reported before any data problem.
  const std::size_t col_dv = table.column(columns.dv);
  const std::size_t col_subject = table.column(columns.subject);
  std::vector<std::size_t> col_within, col_between;
  for (const auto& w : columns.within) col_within.push_back(table.column(w));
  for (const auto& b : columns.between) col_between.push_back(table.column(b));
  const SourceLocation header_at{table.file(), 1, 0};
  if (columns.within.empty()) throw InputError(SourceLocation{}, "--within: need at least one within-subject factor");
  {
    std::vector<std::string> all{columns.dv, columns.subject};
    all.insert(all.end(), columns.within.begin(), columns.within.end());
    all.insert(all.end(), columns.between.begin(), columns.between.end());
    for (std::size_t i = 0; i < all.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (all[i] == all[j]) throw InputError(SourceLocation{}, "column '" + all[i] + "' is used twice in the design");
  }
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");

  RmData d;
  for (const auto& w : columns.within) d.within.push_back(RmFactor{w, {}});
  for (const auto& b : columns.between) d.between.push_back(RmFactor{b, {}});
  std::vector<std::unordered_map<std::string, int>> within_index(d.within.size()), between_index(d.between.size());
  std::unordered_map<std::string, int> subject_index;

  // First pass: levels, subjects and per-row codes.
  struct Coded {
    int subject;
    std::vector<int> within, between;
    double dv;
  };
  std::vector<Coded> coded(table.rows());
  std::vector<std::size_t> subject_first_row;
  for (std::size_t r = 0; r < table.rows(); ++r) {
    Coded& c = coded[r];
    c.dv = table.number(r, col_dv);
    const std::string& s = table.cell(r, col_subject);
    if (s.empty()) throw InputError(table.where(r, col_subject), "column '" + columns.subject + "': empty subject id");
    auto [it, added] = subject_index.try_emplace(s, int(d.subjects.size()));
    if (added) {
      d.subjects.push_back(s);
      subject_first_row.push_back(r);
    }
    c.subject = it->second;
    for (std::size_t f = 0; f < d.within.size(); ++f) {
      if (table.cell(r, col_within[f]).empty())
        throw InputError(table.where(r, col_within[f]), "column '" + d.within[f].name + "': empty level");
      c.within.push_back(level_of(d.within[f], within_index[f], table.cell(r, col_within[f])));
    }
    for (std::size_t f = 0; f < d.between.size(); ++f) {
      if (table.cell(r, col_between[f]).empty())
        throw InputError(table.where(r, col_between[f]), "column '" + d.between[f].name + "': empty level");
      c.between.push_back(level_of(d.between[f], between_index[f], table.cell(r, col_between[f])));
    }
  }
  const std::size_t n = d.subjects.size();
  if (n < 2)
    throw InputError(table.where(0, col_subject),
                     "only one subject ('" + d.subjects.front() + "'); a repeated-measures ANOVA needs at least two");
  for (std::size_t f = 0; f < d.within.size(); ++f)
    if (d.within[f].levels.size() < 2)
      throw InputError(table.where(0, col_within[f]),
                       "within factor '" + d.within[f].name + "' has a single level ('" + d.within[f].levels[0] + "')");
  for (std::size_t f = 0; f < d.between.size(); ++f)
    if (d.between[f].levels.size() < 2)
      throw InputError(table.where(0, col_between[f]),
                       "between factor '" + d.between[f].name + "' has a single level ('" + d.between[f].levels[0] + "')");

  // Second pass: sums and counts per subject and cell; between levels constant per subject.
  const std::size_t cells = d.cells();
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(cells));
  Eigen::MatrixXi count = Eigen::MatrixXi::Zero(Eigen::Index(n), Eigen::Index(cells));
  d.between_level = Eigen::MatrixXi::Constant(Eigen::Index(n), Eigen::Index(d.between.size()), -1);
  for (std::size_t r = 0; r < table.rows(); ++r) {
    const Coded& c = coded[r];
    std::size_t cell = 0;
    for (std::size_t f = 0; f < d.within.size(); ++f) cell = cell * d.within[f].levels.size() + std::size_t(c.within[f]);
    sum(c.subject, Eigen::Index(cell)) += c.dv;
    count(c.subject, Eigen::Index(cell)) += 1;
    for (std::size_t f = 0; f < d.between.size(); ++f) {
      int& level = d.between_level(c.subject, Eigen::Index(f));
      if (level < 0) level = c.between[f];
      if (level != c.between[f])
        throw InputError(table.where(r, col_between[f]),
                         "between factor '" + d.between[f].name + "' changes within subject '" +
                             d.subjects[std::size_t(c.subject)] + "' (was '" + d.between[f].levels[std::size_t(level)] +
                             "')");
    }
  }
  std::size_t averaged = 0;
  for (std::size_t s = 0; s < n; ++s)
    for (std::size_t cell = 0; cell < cells; ++cell) {
      const int k = count(Eigen::Index(s), Eigen::Index(cell));
      if (k == 0)
        throw InputError(table.where(subject_first_row[s], col_subject),
                         "subject '" + d.subjects[s] + "' has no observation for " + cell_label(d.within, cell) +
                             " (every subject needs every within cell)");
      averaged += k > 1;
    }
  d.cell_mean = sum.array() / count.cast<double>().array();
  if (averaged > 0)
    notices.push_back("more than one observation per design cell (" + std::to_string(averaged) + " of " +
                      std::to_string(n * cells) + " subject cells); aggregating with the mean, as afex does");

  // Between cells must all hold subjects, and leave error degrees of freedom.
  if (!d.between.empty()) {
    std::size_t combos = 1;
    for (const auto& f : d.between) combos *= f.levels.size();
    std::vector<int> seen(combos, 0);
    for (std::size_t s = 0; s < n; ++s) {
      std::size_t k = 0;
      for (std::size_t f = 0; f < d.between.size(); ++f)
        k = k * d.between[f].levels.size() + std::size_t(d.between_level(Eigen::Index(s), Eigen::Index(f)));
      seen[k] = 1;
    }
    for (std::size_t k = 0; k < combos; ++k)
      if (!seen[k]) throw InputError(header_at, "a combination of between-subject levels has no subjects");
    if (n <= combos)
      throw InputError(header_at, "too few subjects (" + std::to_string(n) + ") for " + std::to_string(combos) +
                                      " between-subject groups: no error degrees of freedom");
  }
  return d;
}

}  // namespace ms
