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

// The table's column of each design variable. Every column is resolved, and the design checked,
// before any row is read, so a missing column is reported before any data problem.
struct DesignColumns {
  std::size_t dv, subject;
  std::vector<std::size_t> within, between;
};

DesignColumns design_columns(const TidyCsv& table, const RmColumns& columns) {
  DesignColumns cols{table.column(columns.dv), table.column(columns.subject), {}, {}};
  for (const auto& w : columns.within) cols.within.push_back(table.column(w));
  for (const auto& b : columns.between) cols.between.push_back(table.column(b));
  if (columns.within.empty()) throw InputError(SourceLocation{}, "--within: need at least one within-subject factor");
  std::vector<std::string> all{columns.dv, columns.subject};
  all.insert(all.end(), columns.within.begin(), columns.within.end());
  all.insert(all.end(), columns.between.begin(), columns.between.end());
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (all[i] == all[j]) throw InputError(SourceLocation{}, "column '" + all[i] + "' is used twice in the design");
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  return cols;
}

// One row as level indices of the design's factors.
struct CodedRow {
  int subject;
  std::vector<int> within, between;
  double dv;
};

// A factor level of row r, adding it to the factor on first sight; an empty cell is an error.
int coded_level(const TidyCsv& table, std::size_t r, std::size_t col, RmFactor& factor,
                std::unordered_map<std::string, int>& index) {
  if (table.cell(r, col).empty()) throw InputError(table.where(r, col), "column '" + factor.name + "': empty level");
  return level_of(factor, index, table.cell(r, col));
}

// First pass: the subjects and every factor's levels in order of first appearance, each row coded,
// and the row where each subject first appears (for its errors).
std::vector<CodedRow> code_rows(const TidyCsv& table, const RmColumns& columns, const DesignColumns& cols, RmData& d,
                                std::vector<std::size_t>& subject_first_row) {
  std::vector<std::unordered_map<std::string, int>> within_index(d.within.size()), between_index(d.between.size());
  std::unordered_map<std::string, int> subject_index;
  std::vector<CodedRow> coded(table.rows());
  for (std::size_t r = 0; r < table.rows(); ++r) {
    CodedRow& c = coded[r];
    c.dv = table.number(r, cols.dv);
    const std::string& s = table.cell(r, cols.subject);
    if (s.empty()) throw InputError(table.where(r, cols.subject), "column '" + columns.subject + "': empty subject id");
    auto [it, added] = subject_index.try_emplace(s, int(d.subjects.size()));
    if (added) {
      d.subjects.push_back(s);
      subject_first_row.push_back(r);
    }
    c.subject = it->second;
    for (std::size_t f = 0; f < d.within.size(); ++f)
      c.within.push_back(coded_level(table, r, cols.within[f], d.within[f], within_index[f]));
    for (std::size_t f = 0; f < d.between.size(); ++f)
      c.between.push_back(coded_level(table, r, cols.between[f], d.between[f], between_index[f]));
  }
  return coded;
}

// At least two subjects, and two levels of every factor.
void check_levels(const TidyCsv& table, const DesignColumns& cols, const RmData& d) {
  if (d.subjects.size() < 2)
    throw InputError(table.where(0, cols.subject),
                     "only one subject ('" + d.subjects.front() + "'); a repeated-measures ANOVA needs at least two");
  for (std::size_t f = 0; f < d.within.size(); ++f)
    if (d.within[f].levels.size() < 2)
      throw InputError(table.where(0, cols.within[f]),
                       "within factor '" + d.within[f].name + "' has a single level ('" + d.within[f].levels[0] + "')");
  for (std::size_t f = 0; f < d.between.size(); ++f)
    if (d.between[f].levels.size() < 2)
      throw InputError(table.where(0, cols.between[f]),
                       "between factor '" + d.between[f].name + "' has a single level ('" + d.between[f].levels[0] + "')");
}

// Second pass: the mean per subject and within cell (every cell observed, repeats averaged, named in
// a notice), and each subject's between levels, which must not change.
void fill_cell_means(const TidyCsv& table, const DesignColumns& cols, const std::vector<CodedRow>& coded,
                     const std::vector<std::size_t>& subject_first_row, RmData& d, std::vector<std::string>& notices) {
  const std::size_t n = d.subjects.size(), cells = d.cells();
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(cells));
  Eigen::MatrixXi count = Eigen::MatrixXi::Zero(Eigen::Index(n), Eigen::Index(cells));
  d.between_level = Eigen::MatrixXi::Constant(Eigen::Index(n), Eigen::Index(d.between.size()), -1);
  for (std::size_t r = 0; r < table.rows(); ++r) {
    const CodedRow& c = coded[r];
    std::size_t cell = 0;
    for (std::size_t f = 0; f < d.within.size(); ++f) cell = cell * d.within[f].levels.size() + std::size_t(c.within[f]);
    sum(c.subject, Eigen::Index(cell)) += c.dv;
    count(c.subject, Eigen::Index(cell)) += 1;
    for (std::size_t f = 0; f < d.between.size(); ++f) {
      int& level = d.between_level(c.subject, Eigen::Index(f));
      if (level < 0) level = c.between[f];
      if (level != c.between[f])
        throw InputError(table.where(r, cols.between[f]),
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
        throw InputError(table.where(subject_first_row[s], cols.subject),
                         "subject '" + d.subjects[s] + "' has no observation for " + cell_label(d.within, cell) +
                             " (every subject needs every within cell)");
      averaged += k > 1;
    }
  d.cell_mean = sum.array() / count.cast<double>().array();
  if (averaged > 0)
    notices.push_back("more than one observation per design cell (" + std::to_string(averaged) + " of " +
                      std::to_string(n * cells) + " subject cells); aggregating with the mean, as afex does");
}

// Between cells must all hold subjects, and leave error degrees of freedom.
void check_between_groups(const TidyCsv& table, const RmData& d) {
  if (d.between.empty()) return;
  const SourceLocation header_at{table.file(), 1, 0};
  const std::size_t n = d.subjects.size();
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

}  // namespace

RmData rm_data_from_table(const TidyCsv& table, const RmColumns& columns, std::vector<std::string>& notices) {
  const DesignColumns cols = design_columns(table, columns);
  RmData d;
  for (const auto& w : columns.within) d.within.push_back(RmFactor{w, {}});
  for (const auto& b : columns.between) d.between.push_back(RmFactor{b, {}});
  std::vector<std::size_t> subject_first_row;
  const std::vector<CodedRow> coded = code_rows(table, columns, cols, d, subject_first_row);
  check_levels(table, cols, d);
  fill_cell_means(table, cols, coded, subject_first_row, d, notices);
  check_between_groups(table, d);
  return d;
}

}  // namespace ms
