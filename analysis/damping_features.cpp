// Features CSV reader (same conventions and messages as synthesis/modes_csv.cpp) and lambda/c conversion.
#include "analysis/damping_features.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

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
  return cells;
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  const auto e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

bool blank_or_comment(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#';
}

}  // namespace

std::vector<DampingFeature> parse_damping_features_csv(const std::string& text, const std::string& file) {
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    ++line_no;
    if (blank_or_comment(line)) continue;
    header = split_csv_line(line);
    break;
  }
  if (header.empty()) throw InputError(SourceLocation{file, 0, 0}, "empty features CSV (no header)");
  int col_sound = -1, col_f = -1, col_d = -1, col_a = -1;
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string name = trimmed(header[i]);
    if (name == "sound") col_sound = int(i);
    if (name == "freq_hz") col_f = int(i);
    if (name == "decay_per_s") col_d = int(i);
    if (name == "amp") col_a = int(i);
  }
  for (auto [col, name] : {std::pair{col_f, "freq_hz"}, {col_d, "decay_per_s"}})
    if (col < 0)
      throw InputError(SourceLocation{file, line_no, 1},
                       std::string("missing column '") + name + "' (need freq_hz,decay_per_s; sound,amp optional)");

  std::vector<DampingFeature> features;
  while (std::getline(in, line)) {
    ++line_no;
    if (blank_or_comment(line)) continue;
    const auto cells = split_csv_line(line);
    if (cells.size() != header.size())
      throw InputError(SourceLocation{file, line_no, 1}, "expected " + std::to_string(header.size()) +
                                                             " cells, got " + std::to_string(cells.size()));
    // Column of a cell: 1-based character position of its first character in the raw line.
    auto column_of = [&](int col) {
      int column = 1;
      for (int c = 0; c < col; ++c) column += int(cells[std::size_t(c)].size()) + 1;
      return column;
    };
    auto value = [&](int col, const char* name) {
      const std::string s = trimmed(cells[std::size_t(col)]);
      const SourceLocation where{file, line_no, column_of(col)};
      double v = 0.0;
      auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
      if (s.empty() || ec != std::errc() || ptr != s.data() + s.size())
        throw InputError(where, std::string(name) + ": expected a number, got '" + s + "'");
      if (!std::isfinite(v)) throw InputError(where, std::string(name) + ": not a finite number ('" + s + "')");
      return std::pair{v, where};
    };
    DampingFeature f;
    f.line = line_no;
    if (col_sound >= 0) f.sound = trimmed(cells[std::size_t(col_sound)]);
    SourceLocation wf, wd;
    std::tie(f.freq_hz, wf) = value(col_f, "freq_hz");
    std::tie(f.decay_per_s, wd) = value(col_d, "decay_per_s");
    if (!(f.freq_hz > 0)) throw InputError(wf, "freq_hz must be greater than 0");
    // A measured mode always decays; 0 or negative is an extraction failure (and breaks log-space fits).
    if (!(f.decay_per_s > 0)) throw InputError(wd, "decay_per_s must be greater than 0");
    if (col_a >= 0) {
      SourceLocation wa;
      std::tie(f.amp, wa) = value(col_a, "amp");
      if (f.amp < 0) throw InputError(wa, "amp must not be negative");
    }
    features.push_back(f);
  }
  if (features.empty()) throw InputError(SourceLocation{file, line_no, 0}, "features CSV has no rows");
  return features;
}

std::vector<DampingFeature> read_damping_features_csv(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(SourceLocation{path, 0, 0}, "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path, 0, 0}, "cannot read file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_damping_features_csv(buffer.str(), path);
}

DampingPoint damping_point(double freq_hz, double decay_per_s) {
  const double omega_d = 2.0 * M_PI * freq_hz;
  return DampingPoint{omega_d * omega_d + decay_per_s * decay_per_s, 2.0 * decay_per_s};
}

std::vector<DampingPoint> damping_points(const std::vector<DampingFeature>& features) {
  std::vector<DampingPoint> points;
  points.reserve(features.size());
  for (const auto& f : features) points.push_back(damping_point(f.freq_hz, f.decay_per_s));
  return points;
}

}  // namespace ms
