#include "synthesis/modes_csv.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "synthesis/atomic_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

namespace {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (char c : line) {
    if (c == ',') {
      cells.push_back(cell);
      cell.clear();
    } else if (c != '\r') {
      cell += c;
    }
  }
  cells.push_back(cell);
  for (auto& s : cells) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t");
    s = b == std::string::npos ? "" : s.substr(b, e - b + 1);
  }
  return cells;
}

}  // namespace

ModalModel parse_modes_csv(const std::string& text, const std::string& file,
                           std::vector<int>* line_of_mode) {
  if (line_of_mode) line_of_mode->clear();
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    header = split_csv_line(line);
    break;
  }
  if (header.empty()) throw InputError(SourceLocation{file, 0, 0}, "empty modes CSV (no header)");
  int col_f = -1, col_d = -1, col_a = -1, col_p = -1;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "freq_hz") col_f = int(i);
    if (header[i] == "decay_per_s") col_d = int(i);
    if (header[i] == "amp") col_a = int(i);
    if (header[i] == "phase_rad") col_p = int(i);
  }
  for (auto [col, name] : {std::pair{col_f, "freq_hz"}, {col_d, "decay_per_s"}, {col_a, "amp"}})
    if (col < 0)
      throw InputError(SourceLocation{file, line_no, 0}, std::string("missing column '") + name +
                                                             "' (need freq_hz,decay_per_s,amp)");
  ModalModel model;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    const auto cells = split_csv_line(line);
    if (cells.size() != header.size())
      throw InputError(SourceLocation{file, line_no, 0},
                       "expected " + std::to_string(header.size()) + " cells, got " +
                           std::to_string(cells.size()));
    auto value = [&](int col, const char* name) {
      const std::string& s = cells[std::size_t(col)];
      double v = 0.0;
      auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
      // Column number: 1-based character position of the cell.
      int column = 1;
      for (int c = 0; c < col; ++c) column += int(cells[std::size_t(c)].size()) + 1;
      const SourceLocation where{file, line_no, column};
      if (ec != std::errc() || ptr != s.data() + s.size() || s.empty())
        throw InputError(where, std::string(name) + ": expected a number, got '" + s + "'");
      if (!std::isfinite(v)) throw InputError(where, std::string(name) + ": not a finite number");
      return std::pair{v, where};
    };
    auto [f, wf] = value(col_f, "freq_hz");
    auto [d, wd] = value(col_d, "decay_per_s");
    auto [a, wa] = value(col_a, "amp");
    if (!(f > 0)) throw InputError(wf, "freq_hz must be greater than 0");
    if (d < 0) throw InputError(wd, "decay_per_s must not be negative");
    if (a < 0) throw InputError(wa, "amp must not be negative");
    const double phase = col_p >= 0 ? value(col_p, "phase_rad").first : 0.0;
    model.modes.push_back(Mode{f, d, a, phase});
    if (line_of_mode) line_of_mode->push_back(line_no);
  }
  if (model.modes.empty()) throw InputError(SourceLocation{file, line_no, 0}, "modes CSV has no modes");
  return model;
}

ModalModel read_modes_csv(const std::string& path, std::vector<int>* line_of_mode) {
  if (!std::filesystem::exists(path)) throw InputError(SourceLocation{path, 0, 0}, "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path, 0, 0}, "cannot read file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_modes_csv(buffer.str(), path, line_of_mode);
}

void write_modes_csv(const std::string& path, const ModalModel& model) {
  std::string out = "freq_hz,decay_per_s,amp,phase_rad\n";
  char buf[128];
  for (const Mode& m : model.modes) {
    std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g,%.17g\n", m.freq_hz, m.decay_per_s, m.amp,
                  m.phase_rad);
    out += buf;
  }
  write_file_atomically(path, out);
}

}  // namespace ms
