// A double as the shortest text that reads back to exactly the same value ("0.1", "3", "1e-05"):
// std::to_chars without a precision. Every file written to be read back (parameter sets, material
// and residual files, CSV cells) writes its numbers with it, so writing and reading lose nothing.
#pragma once
#include <charconv>
#include <string>

namespace ms {

inline std::string exact_number(double v) {
  char buf[64];  // the longest shortest form of a double is 24 characters
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace ms
