// InputError: the one exception type for bad files and bad values a person wrote.
// what() is a single line "FILE:LINE:COL: problem" (parts omitted when unknown).
#pragma once
#include <stdexcept>
#include <string>

namespace ms {

struct SourceLocation {
  std::string file;  // empty when the value came from the command line
  int line = 0;      // 1-based; 0 = unknown
  int column = 0;    // 1-based; 0 = unknown
};

class InputError : public std::runtime_error {
 public:
  InputError(const SourceLocation& where, const std::string& problem);
  explicit InputError(const std::string& problem) : InputError(SourceLocation{}, problem) {}
  const SourceLocation& where() const { return where_; }
  const std::string& problem() const { return problem_; }

 private:
  SourceLocation where_;
  std::string problem_;
};

std::string format_location(const SourceLocation& where);

}  // namespace ms
