#include "synthesis/tidy_csv.hpp"

#include <charconv>
#include <cmath>

#include "synthesis/csv.hpp"

namespace ms {

TidyCsv TidyCsv::parse(const std::string& text, const std::string& file) {
  TidyCsv t;
  t.file_ = file;
  auto records = csv::parse(text, file);
  if (records.empty()) throw InputError(SourceLocation{file, 0, 0}, "empty CSV (no header row)");
  t.header_ = records.front().cells;
  t.header_line_ = records.front().where.front().line;
  for (std::size_t c = 0; c < t.header_.size(); ++c) {
    const SourceLocation& at = records.front().where[c];
    // An empty first name is the row-names column R's write.csv and pandas' to_csv write.
    if (t.header_[c].empty() && c > 0) throw InputError(at, "empty column name in header");
    for (std::size_t d = 0; d < c; ++d)
      if (t.header_[d] == t.header_[c]) throw InputError(at, "duplicate column name '" + t.header_[c] + "'");
  }
  for (std::size_t r = 1; r < records.size(); ++r) {
    auto& rec = records[r];
    if (rec.cells.size() != t.header_.size()) {
      // Too many: point at the first extra cell; too few: at the start of the row.
      const auto& at = rec.where[rec.cells.size() > t.header_.size() ? t.header_.size() : 0];
      throw InputError(at, "expected " + std::to_string(t.header_.size()) + " cells (as in the header), got " +
                               std::to_string(rec.cells.size()));
    }
    t.cells_.push_back(std::move(rec.cells));
    std::vector<std::pair<int, int>> pos;
    for (const auto& w : rec.where) pos.emplace_back(w.line, w.column);
    t.positions_.push_back(std::move(pos));
  }
  return t;
}

TidyCsv TidyCsv::read(const std::string& path) { return parse(csv::read_file(path), path); }

TidyCsv TidyCsv::keep_rows(const std::vector<std::size_t>& rows) const {
  TidyCsv t;
  t.file_ = file_;
  t.header_ = header_;
  t.header_line_ = header_line_;
  for (std::size_t r : rows) {
    t.cells_.push_back(cells_.at(r));
    t.positions_.push_back(positions_.at(r));
  }
  return t;
}

bool TidyCsv::has_column(const std::string& name) const {
  for (const auto& h : header_)
    if (h == name) return true;
  return false;
}

std::size_t TidyCsv::first_column(const std::vector<std::string>& names) const {
  for (const auto& n : names)
    if (has_column(n)) return column(n);
  std::string wanted, have;
  for (const auto& n : names) wanted += (wanted.empty() ? "'" : " or '") + n + "'";
  for (const auto& h : header_) have += (have.empty() ? "" : ", ") + h;
  throw InputError(SourceLocation{file_, header_line_, 1}, "missing column " + wanted + " (columns are: " + have + ")");
}

std::size_t TidyCsv::column(const std::string& name) const {
  for (std::size_t c = 0; c < header_.size(); ++c)
    if (header_[c] == name) return c;
  std::string have;
  for (const auto& h : header_) have += (have.empty() ? "" : ", ") + h;
  throw InputError(SourceLocation{file_, header_line_, 1},
                   "missing column '" + name + "' (columns are: " + have + ")");
}

SourceLocation TidyCsv::where(std::size_t row, std::size_t col) const {
  const auto& p = positions_[row][col];
  return SourceLocation{file_, p.first, p.second};
}

double TidyCsv::number(std::size_t row, std::size_t col) const {
  const std::string& s = cells_[row][col];
  double v = 0.0;
  const char* first = s.data();
  if (!s.empty() && s[0] == '+') ++first;  // from_chars rejects a leading '+'
  auto [ptr, ec] = std::from_chars(first, s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size())
    throw InputError(where(row, col), "column '" + header_[col] + "': expected a number, got '" + s + "'");
  if (!std::isfinite(v))
    throw InputError(where(row, col), "column '" + header_[col] + "': not a finite number ('" + s + "')");
  return v;
}

}  // namespace ms
