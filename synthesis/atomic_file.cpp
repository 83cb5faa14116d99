#include "synthesis/atomic_file.hpp"

#include <atomic>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "synthesis/input_error.hpp"

namespace ms {

namespace fs = std::filesystem;

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  static std::atomic<unsigned> counter{0};
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir))
    throw InputError(SourceLocation{path, 0, 0}, "cannot write: folder '" + dir.string() +
                                                     "' does not exist");
  const std::string temp = (dir / ("." + target.filename().string() + ".tmp" +
                                   std::to_string(::getpid()) + "_" + std::to_string(counter++)))
                               .string();
  try {
    write(temp);
    std::error_code ec;
    fs::rename(temp, target, ec);
    if (ec) throw InputError(SourceLocation{path, 0, 0}, "cannot write: " + ec.message());
  } catch (...) {
    std::error_code ignore;
    fs::remove(temp, ignore);
    throw;
  }
}

void write_file_atomically(const std::string& path, const std::string& content) {
  write_atomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw InputError(SourceLocation{path, 0, 0}, "cannot write: permission denied or bad path");
    out.write(content.data(), std::streamsize(content.size()));
    out.close();
    if (!out) throw InputError(SourceLocation{path, 0, 0}, "cannot write: disk full or I/O error");
  });
}

}  // namespace ms
