// Audio files through libsndfile: read WAV/FLAC/AIFF (any format libsndfile knows) as float,
// write WAV as 32-bit float or 24-bit PCM. Writes are atomic (temporary file, then rename).
#pragma once
#include <string>
#include <vector>

#include "synthesis/name_table.hpp"

namespace ms {

struct Audio {
  double sample_rate_hz = 0.0;
  int channels = 1;
  std::vector<float> samples;  // interleaved, frames * channels
  std::size_t frames() const { return channels > 0 ? samples.size() / std::size_t(channels) : 0; }
};

enum class SampleFormat { float32, pcm24, pcm16 };
inline constexpr NameTable<SampleFormat, 3> kSampleFormatNames{
    {{SampleFormat::float32, "float32"}, {SampleFormat::pcm24, "pcm24"}, {SampleFormat::pcm16, "pcm16"}}};

SampleFormat parse_sample_format(const std::string& name);  // "float32" | "pcm24" | "pcm16"
std::string to_string(SampleFormat format);

// Throws InputError naming the file when it is missing, unreadable or not audio.
Audio read_audio(const std::string& path);

// One channel: mix to mono (channel < 0) or pick a channel (0-based).
std::vector<float> mono(const Audio& audio, int channel = -1);

// Throws InputError when the path cannot be written or a PCM sample would clip.
void write_wav(const std::string& path, const Audio& audio, SampleFormat format);

}  // namespace ms
