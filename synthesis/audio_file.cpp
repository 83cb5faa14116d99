#include "synthesis/audio_file.hpp"

#include <sndfile.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "synthesis/atomic_file.hpp"
#include "synthesis/bounded_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

SampleFormat parse_sample_format(const std::string& name) {
  if (const auto format = find_enum(kSampleFormatNames, name)) return *format;
  throw std::invalid_argument(unknown_name_problem("sample format", name, kSampleFormatNames));
}

std::string to_string(SampleFormat format) { return std::string(enum_name(kSampleFormatNames, format)); }

namespace {

std::uint32_t le32(const unsigned char* b) {
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

// libsndfile reads a RIFF WAV whose data chunk claims more bytes than the file holds as if it were
// whole (it shortens the length without a word), and one whose header claims no samples as empty:
// both are files a writer never finished (a copy cut short, a stream captured to disk). Walks the
// chunk headers only.
std::optional<std::string> wav_header_problem(int fd, std::uint64_t file_size) {
  unsigned char head[12];
  if (::pread(fd, head, sizeof head, 0) != ssize_t(sizeof head)) return std::nullopt;
  if (std::memcmp(head, "RIFF", 4) != 0 || std::memcmp(head + 8, "WAVE", 4) != 0) return std::nullopt;
  std::uint64_t offset = 12;
  for (int chunks = 0; chunks < 4096 && offset + 8 <= file_size; ++chunks) {
    unsigned char chunk[8];
    if (::pread(fd, chunk, sizeof chunk, off_t(offset)) != ssize_t(sizeof chunk)) return std::nullopt;
    const std::uint64_t size = le32(chunk + 4);
    if (std::memcmp(chunk, "data", 4) == 0) {
      const std::uint64_t present = file_size - (offset + 8);
      if (size > present)
        return "truncated: the WAV header declares " + std::to_string(size) + " bytes of samples but only " +
               std::to_string(present) + " follow (the file was cut short or its header is wrong)";
      if (size == 0 && present > 0)
        return "the WAV header declares no samples but " + std::to_string(present) +
               " bytes follow (a header its writer never completed)";
      return std::nullopt;
    }
    offset += 8 + size + (size & 1);
  }
  return std::nullopt;
}

}  // namespace

Audio read_audio(const std::string& path) {
  const SourceLocation where{path, 0, 0};
  const int fd = open_bounded_file(path, kAudioFileLimit);
  struct stat st {};
  const std::uint64_t file_size = ::fstat(fd, &st) == 0 ? std::uint64_t(st.st_size) : 0;
  if (const auto problem = wav_header_problem(fd, file_size)) {
    ::close(fd);
    throw InputError(where, *problem);
  }
  SF_INFO info{};
  SNDFILE* file = sf_open_fd(fd, SFM_READ, &info, SF_TRUE);  // closes fd, also on failure
  if (!file) throw InputError(where, std::string("not a readable audio file (") + sf_strerror(nullptr) + ")");
  if (info.channels <= 0 || info.frames < 0 || info.samplerate <= 0) {
    sf_close(file);
    throw InputError(where, "not a readable audio file (no channels, frames or sample rate)");
  }
  if (std::uint64_t(info.frames) * std::uint64_t(info.channels) > kMaxAudioSamples) {
    sf_close(file);
    throw InputError(where, "declares " + std::to_string(info.frames) + " frames of " + std::to_string(info.channels) +
                                " channel(s), more than the " + std::to_string(kMaxAudioSamples) +
                                " samples an audio file may have");
  }
  Audio audio;
  audio.sample_rate_hz = info.samplerate;
  audio.channels = info.channels;
  // In blocks, so that memory follows the samples there are rather than the count a header claims.
  constexpr sf_count_t kBlockFrames = 1 << 16;
  sf_count_t got = 0;
  while (got < info.frames) {
    const sf_count_t want = std::min(kBlockFrames, info.frames - got);
    audio.samples.resize(std::size_t(got + want) * std::size_t(info.channels));
    const sf_count_t n = sf_readf_float(file, audio.samples.data() + std::size_t(got) * std::size_t(info.channels), want);
    got += std::max<sf_count_t>(n, 0);
    if (n < want) break;
  }
  audio.samples.resize(std::size_t(got) * std::size_t(info.channels));
  sf_close(file);
  if (got != info.frames)
    throw InputError(where, "truncated: " + std::to_string(got) + " of the " + std::to_string(info.frames) +
                                " frames its header declares could be read");
  for (float v : audio.samples)
    if (!std::isfinite(v)) throw InputError(where, "audio contains NaN or infinite samples");
  return audio;
}

std::vector<float> mono(const Audio& audio, int channel) {
  const std::size_t frames = audio.frames(), ch = std::size_t(audio.channels);
  std::vector<float> out(frames, 0.0f);
  if (channel >= audio.channels) throw std::invalid_argument("channel out of range");
  for (std::size_t n = 0; n < frames; ++n) {
    if (channel >= 0) {
      out[n] = audio.samples[n * ch + std::size_t(channel)];
    } else {
      double sum = 0.0;
      for (std::size_t c = 0; c < ch; ++c) sum += audio.samples[n * ch + c];
      out[n] = float(sum / double(ch));
    }
  }
  return out;
}

void write_wav(const std::string& path, const Audio& audio, SampleFormat format) {
  const SourceLocation where{path, 0, 0};
  if (format != SampleFormat::float32) {
    for (float v : audio.samples)
      if (std::abs(v) > 1.0f)
        throw InputError(where, "samples exceed full scale; use float32 or normalize: peak");
  }
  for (float v : audio.samples)
    if (!std::isfinite(v)) throw InputError(where, "refusing to write NaN or infinite samples");
  write_atomically(path, [&](const std::string& temp) {
    SF_INFO info{};
    info.samplerate = int(std::lround(audio.sample_rate_hz));
    info.channels = audio.channels;
    info.format = SF_FORMAT_WAV | (format == SampleFormat::float32 ? SF_FORMAT_FLOAT
                                   : format == SampleFormat::pcm24 ? SF_FORMAT_PCM_24
                                                                   : SF_FORMAT_PCM_16);
    SNDFILE* file = sf_open(temp.c_str(), SFM_WRITE, &info);
    if (!file) throw InputError(where, std::string("cannot write (") + sf_strerror(nullptr) + ")");
    // Scale float to PCM by 2^(bits-1) with clipping at full scale (libsndfile's default would wrap).
    sf_command(file, SFC_SET_CLIPPING, nullptr, SF_TRUE);
    const sf_count_t frames = sf_count_t(audio.frames());
    const sf_count_t put = sf_writef_float(file, audio.samples.data(), frames);
    const int close_error = sf_close(file);
    if (put != frames || close_error != 0) throw InputError(where, "write failed (disk full?)");
  });
}

}  // namespace ms
