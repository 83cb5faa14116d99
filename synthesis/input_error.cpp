#include "synthesis/input_error.hpp"

namespace ms {

std::string format_location(const SourceLocation& where) {
  std::string s = where.file;
  if (where.line > 0) {
    s.append(s.empty() ? "line " : ":");
    s.append(std::to_string(where.line));
    if (where.column > 0) {
      s.push_back(':');
      s.append(std::to_string(where.column));
    }
  }
  return s;
}

static std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

InputError::InputError(const SourceLocation& where, const std::string& problem)
    : std::runtime_error(one_line(format_location(where).empty()
                                      ? problem
                                      : format_location(where) + ": " + problem)),
      where_(where),
      problem_(problem) {}

}  // namespace ms
