#include "synthesis/modes_csv.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "synthesis/atomic_file.hpp"
#include "synthesis/csv.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

ModalModel parse_modes_csv(const std::string& text, const std::string& file,
                           std::vector<int>* line_of_mode) {
  if (line_of_mode) line_of_mode->clear();
  const std::vector<csv::Record> records = csv::parse(text, file);
  if (records.empty()) throw InputError(SourceLocation{file, 0, 0}, "empty modes CSV (no header)");
  const csv::Record& head = records.front();
  const std::vector<std::string>& header = head.cells;
  int col_f = -1, col_d = -1, col_a = -1, col_p = -1;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == "freq_hz") col_f = int(i);
    if (header[i] == "decay_per_s") col_d = int(i);
    if (header[i] == "amp") col_a = int(i);
    if (header[i] == "phase_rad") col_p = int(i);
  }
  for (auto [col, name] : {std::pair{col_f, "freq_hz"}, {col_d, "decay_per_s"}, {col_a, "amp"}})
    if (col < 0)
      throw InputError(head.where.front(), std::string("missing column '") + name + "' (need freq_hz,decay_per_s,amp)");
  ModalModel model;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const csv::Record& rec = records[r];
    const auto& cells = rec.cells;
    // At the first cell too many, or at the last cell of a row that ends early (naming what is missing).
    if (cells.size() > header.size())
      throw InputError(rec.where[header.size()], "expected " + std::to_string(header.size()) + " cells, got " +
                                                     std::to_string(cells.size()));
    if (cells.size() < header.size())
      throw InputError(rec.where.back(), "expected " + std::to_string(header.size()) + " cells, got " +
                                             std::to_string(cells.size()) + " (no '" + header[cells.size()] + "')");
    auto value = [&](int col, const char* name) {
      const std::string& s = cells[std::size_t(col)];
      const char* first = s.data();
      if (!s.empty() && s[0] == '+') ++first;  // from_chars rejects a leading '+'
      double v = 0.0;
      auto [ptr, ec] = std::from_chars(first, s.data() + s.size(), v);
      const SourceLocation& where = rec.where[std::size_t(col)];
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
    if (line_of_mode) line_of_mode->push_back(rec.where.front().line);
  }
  if (model.modes.empty())
    throw InputError(SourceLocation{file, records.back().where.front().line, 0}, "modes CSV has no modes");
  return model;
}

ModalModel read_modes_csv(const std::string& path, std::vector<int>* line_of_mode) {
  return parse_modes_csv(csv::read_file(path), path, line_of_mode);
}

void write_modes_csv(const std::string& path, const ModalModel& model) {
  std::string out = csv::line({"freq_hz", "decay_per_s", "amp", "phase_rad"});
  char buf[32];
  auto g17 = [&buf](double v) {
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  for (const Mode& m : model.modes) out += csv::line({g17(m.freq_hz), g17(m.decay_per_s), g17(m.amp), g17(m.phase_rad)});
  write_file_atomically(path, out);
}

}  // namespace ms
