// The folders that files named inside a protocol or parameter set may come from. One Confinement is
// applied to every path such a file reaches, transitively (a protocol's stimuli, their parameter sets,
// the sets' modes CSVs): "../../x", "/etc/passwd" or a symbolic link leading out is refused.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "synthesis/input_error.hpp"

namespace ms {

class Confinement {
 public:
  // Files anywhere (--allow-outside, `allow_outside: true`).
  static Confinement anywhere();
  // Files inside one of `folders` (made absolute and canonical here); `where_text` names them in
  // messages, e.g. "the protocol's folder and the project's stimuli/ folder".
  static Confinement within(const std::vector<std::filesystem::path>& folders, std::string where_text,
                            std::string escape_hint);

  bool unrestricted() const { return unrestricted_; }
  const std::vector<std::filesystem::path>& roots() const { return roots_; }
  const std::string& where_text() const { return where_text_; }

  // True when `path` (resolved against the current folder, symbolic links followed) lies inside a root.
  bool allows(const std::filesystem::path& path) const;
  // `written` resolved against `base_dir`, canonical as far as it exists. The problem when it is
  // outside, or "" when it is allowed.
  std::filesystem::path resolve(const std::string& written, const std::string& base_dir) const;
  std::string problem(const std::string& written, const std::string& base_dir) const;

 private:
  bool unrestricted_ = true;
  std::vector<std::filesystem::path> roots_;
  std::string where_text_, escape_hint_;
};

// A parameter set read on its own: files in its folder and, when that lies inside a folder named
// stimuli/, anywhere in that stimuli/ folder.
Confinement paramset_confinement(const std::string& paramset_dir);

// Canonical form of `p` as far as it exists (symbolic links followed), lexically normal beyond.
std::filesystem::path canonical_or_self(const std::filesystem::path& p);

}  // namespace ms
