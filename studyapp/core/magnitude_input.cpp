// read_magnitude: std::from_chars on the text with a decimal comma turned into a point.
#include "studyapp/core/magnitude_input.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace ms {

MagnitudeEntry read_magnitude(const std::string& text, bool zero_allowed) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  std::string s = text.substr(first, text.find_last_not_of(" \t") - first + 1);
  const auto commas = std::count(s.begin(), s.end(), ',');
  const auto points = std::count(s.begin(), s.end(), '.');
  if (commas + points > 1) return {std::nullopt, "Write one number with at most one decimal mark, e.g. 12.5 or 12,5."};
  std::replace(s.begin(), s.end(), ',', '.');
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, std::chars_format::fixed);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
    return {std::nullopt, "'" + text + "' is not a number: type digits only, e.g. 50 or 12,5."};
  if (v < 0.0) return {std::nullopt, "The number cannot be negative: 0 would mean no difference at all."};
  if (v == 0.0 && !zero_allowed)
    return {std::nullopt, "Type a number above 0: every pair here differs at least a little."};
  return {v, ""};
}

MagnitudeEntry read_magnitude(const std::string& text, const MagnitudeBlock& block) {
  if (!block.scale) return read_magnitude(text, block.identical_pairs);
  MagnitudeEntry e = read_magnitude(text, true);
  if (e.value && (*e.value < block.scale->min || *e.value > block.scale->max)) {
    char range[80];
    std::snprintf(range, sizeof range, "Type a number from %g to %g.", block.scale->min, block.scale->max);
    return {std::nullopt, range};
  }
  return e;
}

}  // namespace ms
