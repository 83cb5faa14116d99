// Tidy CSV tables (one observation per row, a header row naming the columns) for the statistics
// commands: cell lookup by column name, numeric conversion with FILE:LINE:COLUMN errors.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "synthesis/input_error.hpp"

namespace ms {

// A parsed CSV file, split by synthesis/csv.hpp (RFC 4180: quotes, CRLF, a UTF-8 BOM; blank and
// '#' lines skipped, unquoted fields trimmed). The header's first name may be empty: the row-names
// column of R's write.csv and pandas' to_csv.
class TidyCsv {
 public:
  // Parses `text`; `file` names the source in error messages. Throws InputError for an empty table,
  // an unterminated quote, an empty or duplicate column name (but the first) or a row whose cell
  // count differs from the header's.
  static TidyCsv parse(const std::string& text, const std::string& file);
  // Reads and parses a file (InputError "no such file" / "cannot read file").
  static TidyCsv read(const std::string& path);

  const std::string& file() const { return file_; }
  const std::vector<std::string>& header() const { return header_; }
  std::size_t rows() const { return cells_.size(); }

  // Index of a named column; InputError at the header line listing the columns there are.
  std::size_t column(const std::string& name) const;
  bool has_column(const std::string& name) const;
  // Index of the first of `names` the table has (the same column under another tool's name);
  // InputError at the header line naming them all otherwise.
  std::size_t first_column(const std::vector<std::string>& names) const;

  const std::string& cell(std::size_t row, std::size_t col) const { return cells_[row][col]; }
  // The cell as a finite number; InputError at the cell's FILE:LINE:COLUMN otherwise.
  double number(std::size_t row, std::size_t col) const;
  // Where a cell starts in the file (1-based line and character column).
  SourceLocation where(std::size_t row, std::size_t col) const;
  // Where a row starts.
  SourceLocation where(std::size_t row) const { return where(row, 0); }

  // The same table with only `rows` (in that order); cells keep their file positions.
  TidyCsv keep_rows(const std::vector<std::size_t>& rows) const;

 private:
  std::string file_;
  std::vector<std::string> header_;
  int header_line_ = 0;
  std::vector<std::vector<std::string>> cells_;
  std::vector<std::vector<std::pair<int, int>>> positions_;  // (line, column) per cell
};

}  // namespace ms
