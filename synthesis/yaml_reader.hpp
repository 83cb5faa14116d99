// Strict reading of YAML documents written by people: every value is checked for type, finiteness
// and range, every map for unknown keys (with the nearest valid key suggested), and every problem is
// an InputError naming file:line:column. Shared by parameter sets and protocols.
#pragma once
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "synthesis/input_error.hpp"

namespace ms {

class YamlReader {
 public:
  // `file` is used in messages; `overridden` lists dotted keys whose values came from --set.
  YamlReader(std::string file, std::vector<std::string> overridden = {})
      : file_(std::move(file)), overridden_(std::move(overridden)) {}

  // Parses text; YAML syntax errors become InputError with the parser's line and column, and so do a
  // key written twice in one map (both places named) and aliases expanding past 4 million values.
  YAML::Node load(const std::string& text) const;

  SourceLocation where(const YAML::Node& node, const std::string& key_path) const;
  [[noreturn]] void fail(const YAML::Node& node, const std::string& key_path,
                         const std::string& problem) const;

  // Rejects keys of `map` not in `allowed`; requires `map` to be a map.
  void check_keys(const YAML::Node& map, const std::string& key_path,
                  std::initializer_list<const char*> allowed) const;

  double number(const YAML::Node& node, const std::string& key_path) const;  // finite
  double positive(const YAML::Node& node, const std::string& key_path) const;     // > 0
  double non_negative(const YAML::Node& node, const std::string& key_path) const; // >= 0
  long long integer(const YAML::Node& node, const std::string& key_path) const;
  std::string text(const YAML::Node& node, const std::string& key_path) const;
  // Text that names something in file names and databases (is_identifier).
  std::string identifier(const YAML::Node& node, const std::string& key_path) const;
  std::vector<double> numbers(const YAML::Node& node, const std::string& key_path) const;

  const std::string& file() const { return file_; }

 private:
  // The node's scalar; fails naming `expected` ("a number") where the node is missing (a key its map
  // lacks: asking yaml-cpp anything else of it throws its own error) or is not a scalar.
  const std::string& scalar(const YAML::Node& node, const std::string& key_path, const std::string& expected) const;

  std::string file_;
  std::vector<std::string> overridden_;
};

// Apply "a.b.c=value" overrides to a document (value parsed as YAML). Returns the dotted keys.
std::vector<std::string> apply_overrides(YAML::Node& root, const std::vector<std::string>& sets);

// 1-64 letters, digits, '-', '_' and '.', starting with a letter or digit: safe as a file name part
// (no folder separators, no "..").
bool is_identifier(const std::string& text);

// Levenshtein-nearest candidate, or "" when nothing is close.
std::string nearest_key(const std::string& key, const std::vector<std::string>& candidates);

}  // namespace ms
