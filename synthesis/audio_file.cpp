#include "synthesis/audio_file.hpp"

#include <sndfile.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "synthesis/atomic_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

SampleFormat parse_sample_format(const std::string& name) {
  if (name == "float32") return SampleFormat::float32;
  if (name == "pcm24") return SampleFormat::pcm24;
  if (name == "pcm16") return SampleFormat::pcm16;
  throw std::invalid_argument("unknown sample format '" + name + "' (expected float32, pcm24 or pcm16)");
}

std::string to_string(SampleFormat format) {
  switch (format) {
    case SampleFormat::float32: return "float32";
    case SampleFormat::pcm24: return "pcm24";
    case SampleFormat::pcm16: return "pcm16";
  }
  return "?";
}

Audio read_audio(const std::string& path) {
  const SourceLocation where{path, 0, 0};
  if (!std::filesystem::exists(path)) throw InputError(where, "no such file");
  if (std::filesystem::is_directory(path)) throw InputError(where, "is a folder, not an audio file");
  SF_INFO info{};
  SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
  if (!file) throw InputError(where, std::string("not a readable audio file (") + sf_strerror(nullptr) + ")");
  Audio audio;
  audio.sample_rate_hz = info.samplerate;
  audio.channels = info.channels;
  audio.samples.resize(std::size_t(info.frames) * std::size_t(info.channels));
  const sf_count_t got = sf_readf_float(file, audio.samples.data(), info.frames);
  sf_close(file);
  if (got != info.frames) throw InputError(where, "audio file is truncated");
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
