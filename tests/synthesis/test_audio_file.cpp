// Audio files through libsndfile: round trips, other formats in, atomic and checked writes.
#include <gtest/gtest.h>
#include <sndfile.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/input_error.hpp"

using namespace ms;

namespace {
Audio sine(double fs, int channels, std::size_t frames, double amp) {
  Audio a;
  a.sample_rate_hz = fs;
  a.channels = channels;
  for (std::size_t n = 0; n < frames; ++n)
    for (int c = 0; c < channels; ++c)
      a.samples.push_back(float(amp * std::sin(2 * std::numbers::pi * (440.0 + 100 * c) * n / fs)));
  return a;
}
}  // namespace

TEST(AudioFile, Float32RoundTripIsExact) {
  test::TempDir dir;
  const Audio a = sine(48000, 1, 4800, 1.5);  // float may exceed full scale
  write_wav(dir.file("a.wav"), a, SampleFormat::float32);
  const Audio b = read_audio(dir.file("a.wav"));
  EXPECT_EQ(b.sample_rate_hz, 48000);
  ASSERT_EQ(b.samples.size(), a.samples.size());
  for (std::size_t i = 0; i < a.samples.size(); ++i) ASSERT_EQ(a.samples[i], b.samples[i]);
}

TEST(AudioFile, Pcm24RoundTripWithin24BitQuantisation) {
  test::TempDir dir;
  const Audio a = sine(44100, 2, 4410, 0.9);
  write_wav(dir.file("a.wav"), a, SampleFormat::pcm24);
  const Audio b = read_audio(dir.file("a.wav"));
  EXPECT_EQ(b.channels, 2);
  for (std::size_t i = 0; i < a.samples.size(); ++i) ASSERT_NEAR(a.samples[i], b.samples[i], 1.0 / (1 << 23));
  // Mono mix and channel pick.
  const auto mixed = mono(b), right = mono(b, 1);
  EXPECT_NEAR(mixed[100], 0.5 * (b.samples[200] + b.samples[201]), 1e-7);
  EXPECT_EQ(right[100], b.samples[201]);
}

TEST(AudioFile, ReadsFlacAndAiff) {
  test::TempDir dir;
  for (auto [name, format] : {std::pair{"a.flac", SF_FORMAT_FLAC | SF_FORMAT_PCM_16},
                              std::pair{"a.aiff", SF_FORMAT_AIFF | SF_FORMAT_PCM_24}}) {
    SF_INFO info{};
    info.samplerate = 22050;
    info.channels = 1;
    info.format = format;
    SNDFILE* f = sf_open(dir.file(name).c_str(), SFM_WRITE, &info);
    ASSERT_NE(f, nullptr) << sf_strerror(nullptr);
    const Audio a = sine(22050, 1, 2205, 0.5);
    sf_writef_float(f, a.samples.data(), 2205);
    sf_close(f);
    const Audio b = read_audio(dir.file(name));
    EXPECT_EQ(b.sample_rate_hz, 22050);
    ASSERT_EQ(b.frames(), 2205u);
    EXPECT_NEAR(b.samples[50], a.samples[50], 1e-4) << name;
  }
}

TEST(AudioFile, BadInputsAreClearAndLeaveNothing) {
  test::TempDir dir;
  EXPECT_THROW(read_audio(dir.file("missing.wav")), InputError);
  const std::string text = dir.write("text.wav", "this is not a wav file\n");
  try {
    read_audio(text);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a readable audio file"), std::string::npos) << e.what();
  }
  // PCM cannot hold samples beyond full scale: refuse instead of clipping silently.
  EXPECT_THROW(write_wav(dir.file("loud.wav"), sine(44100, 1, 100, 2.0), SampleFormat::pcm24), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("loud.wav")));
  // Unwritable destination: error, and no temporary left behind.
  EXPECT_THROW(write_wav(dir.file("no/such/folder/a.wav"), sine(44100, 1, 100, 0.5), SampleFormat::float32),
               InputError);
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) files += e.is_regular_file();
  EXPECT_EQ(files, 1u);  // only text.wav
}

TEST(AudioFile, FailedOverwriteKeepsTheOldFile) {
  test::TempDir dir;
  write_wav(dir.file("keep.wav"), sine(44100, 1, 100, 0.5), SampleFormat::float32);
  const auto before = std::filesystem::file_size(dir.file("keep.wav"));
  Audio bad = sine(44100, 1, 100, 0.5);
  bad.samples[3] = std::nanf("");
  EXPECT_THROW(write_wav(dir.file("keep.wav"), bad, SampleFormat::float32), InputError);
  EXPECT_EQ(std::filesystem::file_size(dir.file("keep.wav")), before);
}
