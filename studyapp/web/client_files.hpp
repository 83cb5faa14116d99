// The browser client's files (HTML, CSS, JS modules, SVG), read once from the data folder when the
// server starts and served from memory: a request can only name one of the files found then, so no
// path from a request ever reaches the file system.
#pragma once
#include <map>
#include <optional>
#include <string>

#include "studyapp/web/web_request.hpp"

namespace ms::web {

class ClientFiles {
 public:
  // Reads every .html/.css/.js/.svg file under `folder` (sub-folders too). Throws InputError naming the
  // folder if it does not exist or holds no index.html.
  explicit ClientFiles(const std::string& folder);

  // The file at "/client/<relative path>", or nullopt.
  std::optional<WebResponse> get(const std::string& path) const;
  WebResponse index() const;  // index.html (every participant link's page)
  std::size_t size() const { return files_.size(); }

 private:
  std::map<std::string, WebResponse> files_;  // "/client/app.js" -> response
};

// The client folder beside the running binary: <bin>/../share/modalstudy/web (the build copies
// studyapp/web/client there), else `fallback` (the source tree's copy, for a binary run in place).
std::string default_client_folder(const std::string& fallback);

}  // namespace ms::web
