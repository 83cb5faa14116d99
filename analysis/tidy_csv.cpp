#include "analysis/tidy_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ms {

namespace {

struct RawRow {
  std::vector<std::string> cells;
  std::vector<std::pair<int, int>> positions;
  bool skip = false;  // blank or comment line
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// RFC 4180 with leniencies: CRLF or LF, surrounding blanks trimmed from unquoted fields.
std::vector<RawRow> split_records(const std::string& text, const std::string& file) {
  std::vector<RawRow> rows;
  std::size_t i = 0;
  int line = 1, col = 1;
  const std::size_t n = text.size();
  while (i < n) {
    RawRow row;
    // Comment or blank line: skipped whole.
    std::size_t eol = text.find('\n', i);
    if (eol == std::string::npos) eol = n;
    const std::string whole = text.substr(i, eol - i);
    if (whole.find_first_not_of(" \t\r") == std::string::npos || whole[0] == '#') {
      i = eol + 1;
      ++line;
      continue;
    }
    for (;;) {
      std::string cell;
      const std::pair<int, int> start{line, col};
      bool quoted = false;
      // Leading blanks before an opening quote are allowed.
      std::size_t j = i;
      while (j < n && (text[j] == ' ' || text[j] == '\t')) ++j;
      if (j < n && text[j] == '"') {
        quoted = true;
        col += int(j - i) + 1;
        i = j + 1;
        for (;;) {
          if (i >= n) throw InputError(SourceLocation{file, start.first, start.second}, "unterminated quoted field");
          const char c = text[i];
          if (c == '"') {
            if (i + 1 < n && text[i + 1] == '"') {
              cell += '"';
              i += 2;
              col += 2;
              continue;
            }
            ++i;
            ++col;
            break;
          }
          if (c == '\n') {
            ++line;
            col = 1;
          } else {
            ++col;
          }
          cell += c;
          ++i;
        }
        // Only blanks may follow the closing quote.
        while (i < n && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r')) {
          ++i;
          ++col;
        }
        if (i < n && text[i] != ',' && text[i] != '\n')
          throw InputError(SourceLocation{file, line, col}, "unexpected character after closing quote");
      } else {
        while (i < n && text[i] != ',' && text[i] != '\n') {
          if (text[i] != '\r') cell += text[i];
          ++i;
          ++col;
        }
      }
      row.cells.push_back(quoted ? cell : trim(cell));
      row.positions.push_back(start);
      if (i < n && text[i] == ',') {
        ++i;
        ++col;
        continue;
      }
      // End of record.
      ++i;
      ++line;
      col = 1;
      break;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

TidyCsv TidyCsv::parse(const std::string& text, const std::string& file) {
  TidyCsv t;
  t.file_ = file;
  auto records = split_records(text, file);
  if (records.empty()) throw InputError(SourceLocation{file, 0, 0}, "empty CSV (no header row)");
  t.header_ = records.front().cells;
  t.header_line_ = records.front().positions.front().first;
  for (std::size_t c = 0; c < t.header_.size(); ++c) {
    if (t.header_[c].empty())
      throw InputError(SourceLocation{file, t.header_line_, records.front().positions[c].second},
                       "empty column name in header");
    for (std::size_t d = 0; d < c; ++d)
      if (t.header_[d] == t.header_[c])
        throw InputError(SourceLocation{file, t.header_line_, records.front().positions[c].second},
                         "duplicate column name '" + t.header_[c] + "'");
  }
  for (std::size_t r = 1; r < records.size(); ++r) {
    auto& rec = records[r];
    if (rec.cells.size() != t.header_.size()) {
      // Too many: point at the first extra cell; too few: at the start of the row.
      const auto& at = rec.positions[std::min(rec.cells.size(), t.header_.size()) % rec.cells.size()];
      throw InputError(SourceLocation{file, at.first, at.second},
                       "expected " + std::to_string(t.header_.size()) + " cells (as in the header), got " +
                           std::to_string(rec.cells.size()));
    }
    t.cells_.push_back(std::move(rec.cells));
    t.positions_.push_back(std::move(rec.positions));
  }
  return t;
}

TidyCsv TidyCsv::read(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(SourceLocation{path, 0, 0}, "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path, 0, 0}, "cannot read file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse(buffer.str(), path);
}

bool TidyCsv::has_column(const std::string& name) const {
  for (const auto& h : header_)
    if (h == name) return true;
  return false;
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
