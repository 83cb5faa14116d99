// Every file a person names is opened through here, so that no input can hang a command or exhaust
// memory: only regular files are read (a FIFO, a device such as /dev/zero, a socket or a folder is
// refused before a byte is read), and each kind of file has a documented size cap.
#pragma once
#include <cstdint>
#include <string>

namespace ms {

struct FileLimit {
  const char* what;        // "parameter set", ... (for messages)
  std::uint64_t max_bytes;
};

inline constexpr std::uint64_t kMiB = 1024 * 1024;
inline constexpr FileLimit kYamlFileLimit{"YAML file", 16 * kMiB};    // parameter sets, protocols
inline constexpr FileLimit kJsonFileLimit{"JSON file", 16 * kMiB};    // stimuli build's manifest
inline constexpr FileLimit kCsvFileLimit{"CSV file", 256 * kMiB};     // modes, features, tidy data
inline constexpr FileLimit kAudioFileLimit{"audio file", 2048 * kMiB}; // recordings, rendered stimuli
// Decoded audio: at most this many samples (frames x channels), 1 GiB as float; a compressed file
// (FLAC) can declare far more than its size suggests.
inline constexpr std::uint64_t kMaxAudioSamples = std::uint64_t(1) << 28;

// Opens `path` for reading; returns a descriptor the caller owns (close() it or hand it to a library
// that does). Throws InputError naming the file when it is missing, unreadable, not a regular file
// or larger than `limit`. The checks are made on the opened descriptor, so a path swapped after the
// check cannot slip through, and the open itself never blocks (O_NONBLOCK: a FIFO without writer).
int open_bounded_file(const std::string& path, const FileLimit& limit);

// The whole content of a regular file of at most limit.max_bytes (also enforced while reading, for
// files whose size the file system does not know in advance, such as those under /proc).
std::string read_bounded_file(const std::string& path, const FileLimit& limit);

// The size cap as people read it ("16 MiB").
std::string format_bytes(std::uint64_t bytes);

}  // namespace ms
