#include "synthesis/yaml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

namespace ms {

namespace {

// Nodes a document may expand to through aliases: a reader walking the tree must not do 2^n work
// for n nested aliases ("billion laughs").
constexpr std::uint64_t kMaxExpandedNodes = 4000000;  // 200000 inline modes take 1.8 million

struct TreeCheck {
  const YamlReader& reader;
  // Collections already visited, by start offset (several can share one: "{a: 1}: 2"), each with the
  // nodes below it; 0 while it is being visited.
  std::map<std::size_t, std::vector<std::pair<YAML::Node, std::uint64_t>>> visited;

  std::uint64_t* find(const YAML::Node& n) {
    for (auto& [node, count] : visited[std::size_t(n.Mark().pos)])
      if (node.is(n)) return &count;
    return nullptr;
  }

  // Nodes below `n` with aliases expanded; each collection is walked once (an alias shares its
  // anchor's node).
  std::uint64_t visit(const YAML::Node& n) {
    if (!n.IsMap() && !n.IsSequence()) return 1;
    if (const std::uint64_t* known = find(n)) {
      if (*known == 0) throw InputError(reader.where(n, ""), "an alias refers to a collection that contains it");
      return *known;
    }
    auto& bucket = visited[std::size_t(n.Mark().pos)];
    bucket.emplace_back(n, 0);
    const std::size_t slot = bucket.size() - 1;
    std::uint64_t total = 1;
    if (n.IsMap()) {
      std::map<std::string, YAML::Mark> seen;
      for (auto it = n.begin(); it != n.end() && total <= kMaxExpandedNodes; ++it) {
        if (it->first.IsScalar()) {
          const auto [first, fresh] = seen.emplace(it->first.Scalar(), it->first.Mark());
          if (!fresh)
            throw InputError(reader.where(it->first, ""),
                             "duplicate key '" + it->first.Scalar() + "' (first at line " +
                                 std::to_string(first->second.line + 1) + ", column " +
                                 std::to_string(first->second.column + 1) + ")");
        }
        total += visit(it->first) + visit(it->second);
      }
    } else {
      for (auto it = n.begin(); it != n.end() && total <= kMaxExpandedNodes; ++it) total += visit(*it);
    }
    if (total > kMaxExpandedNodes)
      throw InputError(reader.where(n, ""), "the document expands to more than " +
                                                std::to_string(kMaxExpandedNodes) + " values through aliases");
    visited[std::size_t(n.Mark().pos)][slot].second = total;
    return total;
  }
};

}  // namespace

YAML::Node YamlReader::load(const std::string& text) const {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(SourceLocation{file_, e.mark.line + 1, e.mark.column + 1},
                     "YAML syntax error: " + e.msg);
  }
  TreeCheck{*this, {}}.visit(root);
  return root;
}

SourceLocation YamlReader::where(const YAML::Node& node, const std::string& key_path) const {
  const bool in_file = node.IsDefined() && !node.Mark().is_null();
  for (const auto& o : overridden_)
    if (key_path == o || key_path.rfind(o + ".", 0) == 0 || key_path.rfind(o + "[", 0) == 0 ||
        (!in_file && !key_path.empty() && o.rfind(key_path + ".", 0) == 0))  // a map an override made
      return SourceLocation{"--set " + o, 0, 0};
  if (in_file) return SourceLocation{file_, node.Mark().line + 1, node.Mark().column + 1};
  // The document itself (an empty file): its first line.
  return SourceLocation{file_, key_path.empty() ? 1 : 0, key_path.empty() ? 1 : 0};
}

void YamlReader::fail(const YAML::Node& node, const std::string& key_path,
                      const std::string& problem) const {
  throw InputError(where(node, key_path), key_path.empty() ? problem : key_path + ": " + problem);
}

void YamlReader::check_keys(const YAML::Node& map, const std::string& key_path,
                            std::initializer_list<const char*> allowed) const {
  if (!map.IsDefined() || !map.IsMap()) fail(map, key_path, "expected a map of keys");
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

const std::string& YamlReader::scalar(const YAML::Node& node, const std::string& key_path,
                                      const std::string& expected) const {
  if (!node.IsDefined()) fail(node, key_path, "missing: expected " + expected);
  if (!node.IsScalar()) fail(node, key_path, "expected " + expected);
  return node.Scalar();
}

double YamlReader::number(const YAML::Node& node, const std::string& key_path) const {
  const std::string& s = scalar(node, key_path, "a number");
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
  const std::string& s = scalar(node, key_path, "an integer");
  long long value = 0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || ptr != s.data() + s.size())
    fail(node, key_path, "expected an integer, got '" + s + "'");
  return value;
}

std::string YamlReader::text(const YAML::Node& node, const std::string& key_path) const {
  return scalar(node, key_path, "text");
}

bool is_identifier(const std::string& t) {
  if (t.empty() || t.size() > 64 || !std::isalnum(static_cast<unsigned char>(t[0]))) return false;
  return std::all_of(t.begin(), t.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
  });
}

std::string YamlReader::identifier(const YAML::Node& node, const std::string& key_path) const {
  const std::string t = text(node, key_path);
  if (!is_identifier(t))
    fail(node, key_path, "'" + t + "' is not an id: use 1-64 letters, digits, '-', '_' or '.', starting with a letter or digit");
  return t;
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
