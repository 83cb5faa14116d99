#include "synthesis/path_confinement.hpp"

namespace ms {

namespace fs = std::filesystem;

fs::path canonical_or_self(const fs::path& p) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(p, ec);
  if (ec) return p.lexically_normal();
  const fs::path c = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal() : c;
}

namespace {

// True when `p` lies inside `root` (both canonical): compares whole path components.
bool inside(const fs::path& p, const fs::path& root) {
  auto pi = p.begin();
  for (auto ri = root.begin(); ri != root.end(); ++ri, ++pi) {
    if (ri->empty()) continue;  // trailing separator
    if (pi == p.end() || *pi != *ri) return false;
  }
  return true;
}

}  // namespace

Confinement Confinement::anywhere() { return Confinement{}; }

Confinement Confinement::within(const std::vector<fs::path>& folders, std::string where_text,
                                std::string escape_hint) {
  Confinement c;
  c.unrestricted_ = false;
  for (const auto& f : folders) c.roots_.push_back(canonical_or_self(f));
  c.where_text_ = std::move(where_text);
  c.escape_hint_ = std::move(escape_hint);
  return c;
}

bool Confinement::allows(const fs::path& path) const {
  if (unrestricted_) return true;
  const fs::path resolved = canonical_or_self(path);
  for (const auto& r : roots_)
    if (inside(resolved, r)) return true;
  return false;
}

fs::path Confinement::resolve(const std::string& written, const std::string& base_dir) const {
  const fs::path p(written);
  return canonical_or_self(p.is_absolute() ? p : fs::path(base_dir.empty() ? "." : base_dir) / p);
}

std::string Confinement::problem(const std::string& written, const std::string& base_dir) const {
  if (unrestricted_ || allows(resolve(written, base_dir))) return "";
  return "path '" + written + "' is outside " + where_text_ +
         (escape_hint_.empty() ? "" : " (" + escape_hint_ + ")");
}

Confinement paramset_confinement(const std::string& paramset_dir) {
  const fs::path dir = canonical_or_self(paramset_dir.empty() ? "." : paramset_dir);
  std::vector<fs::path> roots{dir};
  for (fs::path up = dir; up.has_relative_path(); up = up.parent_path())
    if (up.filename() == "stimuli") {
      roots.push_back(up);
      break;
    }
  return Confinement::within(roots, roots.size() > 1 ? "the parameter set's folder and the project's stimuli/ folder"
                                                     : "the parameter set's folder",
                             "use --allow-outside");
}

}  // namespace ms
