#include "synthesis/yaml_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace ms {

YAML::Node YamlReader::load(const std::string& text) const {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(SourceLocation{file_, e.mark.line + 1, e.mark.column + 1},
                     "YAML syntax error: " + e.msg);
  }
}

SourceLocation YamlReader::where(const YAML::Node& node, const std::string& key_path) const {
  for (const auto& o : overridden_)
    if (key_path == o || key_path.rfind(o + ".", 0) == 0 || key_path.rfind(o + "[", 0) == 0)
      return SourceLocation{"--set " + o, 0, 0};
  if (node.IsDefined() && !node.Mark().is_null())
    return SourceLocation{file_, node.Mark().line + 1, node.Mark().column + 1};
  return SourceLocation{file_, 0, 0};
}

void YamlReader::fail(const YAML::Node& node, const std::string& key_path,
                      const std::string& problem) const {
  throw InputError(where(node, key_path), key_path.empty() ? problem : key_path + ": " + problem);
}

void YamlReader::check_keys(const YAML::Node& map, const std::string& key_path,
                            std::initializer_list<const char*> allowed) const {
  if (!map.IsMap()) fail(map, key_path, "expected a map of keys");
  std::vector<std::string> names(allowed.begin(), allowed.end());
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string key = it->first.Scalar();
    if (std::find(names.begin(), names.end(), key) != names.end()) continue;
    const std::string near = nearest_key(key, names);
    const std::string path = key_path.empty() ? key : key_path + "." + key;
    throw InputError(where(it->first, path),
                     "unknown key '" + path + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
  }
}

double YamlReader::number(const YAML::Node& node, const std::string& key_path) const {
  if (!node.IsScalar()) fail(node, key_path, "expected a number");
  const std::string& s = node.Scalar();
  double value = 0.0;
  const char* begin = s.data();
  const char* end = s.data() + s.size();
  if (!s.empty() && *begin == '+') ++begin;
  auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end) {
    const std::string lower = [&] {
      std::string l = s;
      for (char& c : l) c = char(std::tolower(static_cast<unsigned char>(c)));
      return l;
    }();
    if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos)
      fail(node, key_path, "'" + s + "' is not a finite number");
    fail(node, key_path, "expected a number, got '" + s + "'");
  }
  if (!std::isfinite(value)) fail(node, key_path, "'" + s + "' is not a finite number");
  return value;
}

double YamlReader::positive(const YAML::Node& node, const std::string& key_path) const {
  const double v = number(node, key_path);
  if (!(v > 0.0)) fail(node, key_path, "must be greater than 0, got " + node.Scalar());
  return v;
}

double YamlReader::non_negative(const YAML::Node& node, const std::string& key_path) const {
  const double v = number(node, key_path);
  if (v < 0.0) fail(node, key_path, "must not be negative, got " + node.Scalar());
  return v;
}

long long YamlReader::integer(const YAML::Node& node, const std::string& key_path) const {
  if (!node.IsScalar()) fail(node, key_path, "expected an integer");
  const std::string& s = node.Scalar();
  long long value = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || ptr != s.data() + s.size())
    fail(node, key_path, "expected an integer, got '" + s + "'");
  return value;
}

std::string YamlReader::text(const YAML::Node& node, const std::string& key_path) const {
  if (!node.IsScalar()) fail(node, key_path, "expected text");
  return node.Scalar();
}

std::vector<double> YamlReader::numbers(const YAML::Node& node, const std::string& key_path) const {
  if (!node.IsSequence()) fail(node, key_path, "expected a list of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < node.size(); ++i)
    out.push_back(number(node[i], key_path + "[" + std::to_string(i) + "]"));
  return out;
}

std::vector<std::string> apply_overrides(YAML::Node& root, const std::vector<std::string>& sets) {
  std::vector<std::string> keys;
  for (const auto& s : sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(SourceLocation{"--set " + s, 0, 0}, "expected key=value");
    const std::string key = s.substr(0, eq);
    YAML::Node value;
    try {
      value = YAML::Load(s.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      throw InputError(SourceLocation{"--set " + key, 0, 0}, "value is not valid YAML: " + e.msg);
    }
    // Walk/create the dotted path with fresh handles so assignment rebinds, not aliases.
    std::vector<std::string> parts;
    for (std::size_t start = 0;;) {
      const auto dot = key.find('.', start);
      parts.push_back(key.substr(start, dot - start));
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
    std::vector<YAML::Node> chain{root};
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      YAML::Node next = chain.back()[parts[i]];
      if (!next.IsDefined() || !next.IsMap()) {
        if (next.IsDefined() && !next.IsMap())
          throw InputError(SourceLocation{"--set " + key, 0, 0},
                           "'" + parts[i] + "' is not a map and cannot take sub-keys");
        chain.back()[parts[i]] = YAML::Node(YAML::NodeType::Map);
        next = chain.back()[parts[i]];
      }
      chain.push_back(next);
    }
    chain.back()[parts.back()] = value;
    keys.push_back(key);
  }
  return keys;
}

std::string nearest_key(const std::string& key, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(3, key.size() / 3) + 1;
  for (const auto& c : candidates) {
    std::vector<std::size_t> prev(c.size() + 1), cur(c.size() + 1);
    for (std::size_t j = 0; j <= c.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= key.size(); ++i) {
      cur[0] = i;
      for (std::size_t j = 1; j <= c.size(); ++j)
        cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (key[i - 1] != c[j - 1])});
      std::swap(prev, cur);
    }
    // A key that is a prefix of a valid one ("decay" for "decay_per_s") is a near miss too.
    const bool prefix = key.size() >= 3 && c.rfind(key, 0) == 0;
    if (prefix && best_d > 1) {
      best_d = 1;
      best = c;
    }
    if (prev[c.size()] < best_d) {
      best_d = prev[c.size()];
      best = c;
    }
  }
  return best;
}

}  // namespace ms
