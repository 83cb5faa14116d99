// ClientFiles: a fixed map from request paths to file contents, built by walking one folder once.
#include "studyapp/web/client_files.hpp"

#include <filesystem>

#include "synthesis/bounded_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms::web {

namespace fs = std::filesystem;

namespace {

constexpr FileLimit kClientFileLimit{"client file", 4 * kMiB};

std::optional<std::string> content_type(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".js") return "text/javascript; charset=utf-8";
  if (ext == ".svg") return "image/svg+xml";
  return std::nullopt;
}

}  // namespace

ClientFiles::ClientFiles(const std::string& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw InputError(SourceLocation{folder, 0, 0}, "the browser client's folder does not exist");
  for (const auto& entry : fs::recursive_directory_iterator(folder, ec)) {
    if (!entry.is_regular_file()) continue;
    const auto type = content_type(entry.path());
    if (!type) continue;
    WebResponse r;
    r.content_type = *type;
    r.body = read_bounded_file(entry.path().string(), kClientFileLimit);
    r.cacheable = true;
    files_.emplace("/client/" + fs::relative(entry.path(), folder).generic_string(), std::move(r));
  }
  if (!files_.count("/client/index.html"))
    throw InputError(SourceLocation{folder, 0, 0}, "the browser client's folder has no index.html");
}

std::optional<WebResponse> ClientFiles::get(const std::string& path) const {
  const auto it = files_.find(path);
  if (it == files_.end()) return std::nullopt;
  return it->second;
}

WebResponse ClientFiles::index() const {
  WebResponse r = files_.at("/client/index.html");
  r.cacheable = false;
  return r;
}

std::string default_client_folder(const std::string& fallback) {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path beside = exe.parent_path().parent_path() / "share" / "modalstudy" / "web";
    if (fs::is_regular_file(beside / "index.html", ec)) return beside.string();
  }
  return fallback;
}

}  // namespace ms::web
