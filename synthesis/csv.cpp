#include "synthesis/csv.hpp"

#include "synthesis/bounded_file.hpp"
#include "synthesis/exact_number.hpp"

namespace ms::csv {

namespace {

bool blank(char c) { return c == ' ' || c == '\t'; }

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// Reads one record starting at text[i] (at the start of a line) and advances i past its line end.
class Splitter {
 public:
  Splitter(std::string_view text, const std::string& file) : t_(text), file_(file) {
    if (t_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // UTF-8 byte-order mark (Excel, PowerShell)
  }

  bool done() const { return i_ >= t_.size(); }

  // False for a blank or comment line (consumed, nothing returned).
  bool next(Record& rec) {
    rec = Record{};
    std::size_t eol = i_;
    while (eol < t_.size() && t_[eol] != '\n' && t_[eol] != '\r') ++eol;
    const std::string_view whole = t_.substr(i_, eol - i_);
    if (whole.find_first_not_of(" \t") == std::string_view::npos || whole[0] == '#') {
      i_ = eol;
      end_of_line();
      return false;
    }
    for (;;) {
      rec.where.push_back(SourceLocation{file_, line_, col_});
      rec.cells.push_back(cell());
      if (i_ < t_.size() && t_[i_] == ',') {
        advance();
        continue;
      }
      end_of_line();
      return true;
    }
  }

 private:
  void advance() {
    ++i_;
    ++col_;
  }

  // At a line end (or the end of the text): step over CRLF, LF or CR.
  void end_of_line() {
    if (i_ < t_.size() && t_[i_] == '\r') ++i_;
    if (i_ < t_.size() && t_[i_] == '\n') ++i_;
    ++line_;
    col_ = 1;
  }

  bool at_separator() const { return i_ >= t_.size() || t_[i_] == ',' || t_[i_] == '\n' || t_[i_] == '\r'; }

  std::string cell() {
    std::size_t j = i_;
    while (j < t_.size() && blank(t_[j])) ++j;
    if (j >= t_.size() || t_[j] != '"') {
      std::string s;
      while (!at_separator()) {
        s += t_[i_];
        advance();
      }
      return trim(s);
    }
    col_ += int(j - i_);
    i_ = j;
    const SourceLocation open{file_, line_, col_};
    advance();
    std::string s;
    for (;;) {
      if (i_ >= t_.size()) throw InputError(open, "unterminated quoted field");
      const char c = t_[i_];
      if (c == '"') {
        if (i_ + 1 < t_.size() && t_[i_ + 1] == '"') {
          s += '"';
          advance();
          advance();
          continue;
        }
        advance();
        break;
      }
      s += c;
      if (c == '\n' || (c == '\r' && (i_ + 1 >= t_.size() || t_[i_ + 1] != '\n'))) {
        ++i_;
        ++line_;
        col_ = 1;
      } else {
        advance();
      }
    }
    while (i_ < t_.size() && blank(t_[i_])) advance();
    if (!at_separator())
      throw InputError(SourceLocation{file_, line_, col_}, "unexpected character after closing quote");
    return s;
  }

  std::string_view t_;
  const std::string& file_;
  std::size_t i_ = 0;
  int line_ = 1, col_ = 1;
};

bool formula_start(char c) { return c == '=' || c == '+' || c == '-' || c == '@' || c == '\t' || c == '\r'; }

}  // namespace

std::vector<Record> parse(std::string_view text, const std::string& file) {
  std::vector<Record> out;
  Splitter s(text, file);
  Record rec;
  while (!s.done())
    if (s.next(rec)) out.push_back(std::move(rec));
  return out;
}

std::string read_file(const std::string& path) { return read_bounded_file(path, kCsvFileLimit); }

bool is_number(std::string_view s) {
  std::size_t i = 0;
  auto digits = [&] {
    const std::size_t from = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i - from;
  };
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < s.size() && s[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == s.size();
}

std::string field(std::string_view value) {
  std::string v(value);
  bool quote = false;
  if (!v.empty() && formula_start(v[0]) && !is_number(v)) {
    v.insert(v.begin(), '\'');
    quote = true;
  }
  if (v.find_first_of(",\"\r\n") != std::string::npos) quote = true;
  if (!v.empty() && (v[0] == '#' || blank(v.front()) || blank(v.back()))) quote = true;
  if (!quote) return v;
  std::string out = "\"";
  for (char c : v) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string line(const std::vector<std::string>& cells) {
  std::string out;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i) out += ',';
    out += field(cells[i]);
  }
  return out + "\r\n";
}

std::string number(double v) { return exact_number(v); }

}  // namespace ms::csv
