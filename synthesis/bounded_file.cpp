#include "synthesis/bounded_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "synthesis/input_error.hpp"

namespace ms {

std::string format_bytes(std::uint64_t bytes) {
  if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
  if (bytes >= kMiB) return std::to_string(bytes / kMiB) + "." + std::to_string(bytes % kMiB * 10 / kMiB) + " MiB";
  return std::to_string(bytes) + " bytes";
}

namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& problem) {
  throw InputError(SourceLocation{path, 0, 0}, problem);
}

std::string too_large(const FileLimit& limit, std::uint64_t size) {
  return "is " + format_bytes(size) + ", more than the " + format_bytes(limit.max_bytes) + " a " +
         limit.what + " may have";
}

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a folder, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

}  // namespace

int open_bounded_file(const std::string& path, const FileLimit& limit) {
  if (path.empty()) refuse(path, "empty file name");
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    const int err = errno;
    if (err == ENOENT) refuse(path, "no such file");
    if (err == EACCES) refuse(path, "cannot read file (permission denied)");
    if (err == ENOTDIR) refuse(path, "no such file (a part of the path is not a folder)");
    refuse(path, std::string("cannot open file (") + std::strerror(err) + ")");
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    refuse(path, std::string("cannot read file (") + std::strerror(err) + ")");
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    refuse(path, kind_of(st.st_mode));
  }
  if (std::uint64_t(st.st_size) > limit.max_bytes) {
    ::close(fd);
    refuse(path, too_large(limit, std::uint64_t(st.st_size)));
  }
  // Regular files never block; clear the flag so libraries reading the descriptor see plain reads.
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) (void)::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  return fd;
}

std::string read_bounded_file(const std::string& path, const FileLimit& limit) {
  const int fd = open_bounded_file(path, limit);
  std::string content;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      refuse(path, std::string("read error (") + std::strerror(err) + ")");
    }
    if (got == 0) break;
    if (content.size() + std::size_t(got) > limit.max_bytes) {
      ::close(fd);
      refuse(path, "is more than the " + format_bytes(limit.max_bytes) + " a " + limit.what + " may have");
    }
    content.append(buffer, std::size_t(got));
  }
  ::close(fd);
  return content;
}

}  // namespace ms
