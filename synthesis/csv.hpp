// CSV (RFC 4180): the one reader and writer of every CSV file the project reads or writes (modes,
// features, tidy tables, exports). The reader accepts what R's write.csv, pandas' to_csv and
// spreadsheets write; the writer quotes as RFC 4180 requires and neutralises spreadsheet formulas.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "synthesis/input_error.hpp"

namespace ms::csv {

// One record: its cells and where each cell starts (1-based line and byte column of the file).
struct Record {
  std::vector<std::string> cells;
  std::vector<SourceLocation> where;
};

// Splits `text` into records. Accepted besides strict RFC 4180: a UTF-8 byte-order mark; LF or lone
// CR line ends as well as CRLF; blanks around a quoted field; a last line without a line end.
// Unquoted cells are trimmed of surrounding spaces and tabs. Blank lines and lines whose first
// character is '#' (outside quotes) are skipped. Quoted cells keep everything, including line ends.
// Throws InputError at file:line:column for an unterminated quote or text after a closing quote.
std::vector<Record> parse(std::string_view text, const std::string& file);

// The whole file as bytes, through the bounded reader (regular files of at most 256 MiB); InputError
// "no such file", "is a FIFO ...", "is ... more than the 256 MiB a CSV file may have" naming `path`.
std::string read_file(const std::string& path);

// True when `s` is entirely a decimal number: [+-]digits[.digits][e[+-]digits] (no inf, nan, hex).
bool is_number(std::string_view s);

// One cell as written. A cell starting with '=', '+', '-', '@', TAB or CR that is not a number is
// prefixed with a single quote (OWASP's advice against formula injection: a spreadsheet then shows
// it as text), so "=1+2" is written "'=1+2" while "-3" and "+1.5e-3" stay numbers. The cell is quoted
// when it holds a comma, quote, CR or LF, was neutralised, starts with '#' or with/ends in a blank
// (so the reader gives it back exactly).
std::string field(std::string_view value);

// Cells joined by commas, CRLF-terminated (RFC 4180's line end).
std::string line(const std::vector<std::string>& cells);

// A number in its shortest form that reads back to the same double ("0.1", "3", "1e-05").
std::string number(double v);

}  // namespace ms::csv
