// Residual files: writing and reading give back the spectrogram bit for bit, and every broken file is
// one line naming the file (and the header's line and column, or the payload's frame and bin).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <stdexcept>

#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/residual_file.hpp"

using namespace ms;

namespace {

ResidualSpectrogram small_residual() {
  ResidualSpectrogram r;
  r.source = "modalstudy estimate \"spoon\".wav";
  r.sample_rate_hz = 44100.0;
  r.grid = StftGrid{64, 16};
  r.frames = 7;
  r.modes = {Mode{440.0, 3.5, 0.25, 0.1}, Mode{1234.5678901234567, 17.0, 1e-7, -3.0}};
  std::mt19937_64 rng(11);
  std::exponential_distribution<float> e(1.0f);
  r.power.resize(r.frames * r.grid.bins());
  for (float& v : r.power) v = e(rng) * 1e-3f;
  r.power[5] = 0.0f;
  r.power[6] = std::numeric_limits<float>::denorm_min();
  return r;
}

std::string error_of(const std::string& bytes) {
  try {
    parse_residual_file(bytes, "wood.residual.msr");
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    return e.what();
  }
  return "";
}

// The file with `from` in its header replaced by `to`.
std::string with(const std::string& from, const std::string& to) {
  std::string bytes = residual_file_bytes(small_residual());
  const std::size_t at = bytes.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? bytes : bytes.replace(at, from.size(), to);
}

}  // namespace

TEST(ResidualFile, RoundTripsBitForBit) {
  const ResidualSpectrogram r = small_residual();
  test::TempDir dir;
  const std::string path = dir.file("wood.residual.msr");
  write_residual_file(path, r);
  const ResidualSpectrogram back = read_residual_file(path);
  EXPECT_EQ(back.source, r.source);
  EXPECT_EQ(back.sample_rate_hz, r.sample_rate_hz);
  EXPECT_EQ(back.grid.fft_size, r.grid.fft_size);
  EXPECT_EQ(back.grid.hop, r.grid.hop);
  EXPECT_EQ(back.frames, r.frames);
  ASSERT_EQ(back.modes.size(), r.modes.size());
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    EXPECT_EQ(back.modes[i].freq_hz, r.modes[i].freq_hz);
    EXPECT_EQ(back.modes[i].decay_per_s, r.modes[i].decay_per_s);
    EXPECT_EQ(back.modes[i].amp, r.modes[i].amp);
    EXPECT_EQ(back.modes[i].phase_rad, r.modes[i].phase_rad);
  }
  ASSERT_EQ(back.power.size(), r.power.size());
  EXPECT_EQ(std::memcmp(back.power.data(), r.power.data(), r.power.size() * sizeof(float)), 0);
  // The header is readable text: a person can see what the file is.
  const std::string bytes = residual_file_bytes(r);
  EXPECT_EQ(bytes.rfind("format: modalstudy-residual 1\n", 0), 0u);
  EXPECT_NE(bytes.find("stft: {window: hann, fft_size: 64, hop: 16}"), std::string::npos);
  EXPECT_EQ(bytes.size(), bytes.find("\n...\n") + 5 + 4 * r.power.size());
}

TEST(ResidualFile, BrokenHeadersNameTheirLineAndColumn) {
  EXPECT_EQ(error_of("format: modalstudy-residual 1\n"),
            "wood.residual.msr:1:1: not a residual file: no line '...' ends a YAML header");
  EXPECT_EQ(error_of(with("modalstudy-residual 1", "modalstudy-residual 2")),
            "wood.residual.msr:1:9: format: not a residual file (expected 'format: modalstudy-residual 1')");
  EXPECT_NE(error_of(with("frames: 7", "frames: 7\nframez: 3")).find("wood.residual.msr:7:1: "), std::string::npos);
  EXPECT_NE(error_of(with("bins: 33", "bins: 32")).find("bins: must be stft.fft_size / 2 + 1 = 33"), std::string::npos);
  EXPECT_NE(error_of(with("hop: 16", "hop: 40")).find("stft.hop: must lie in 1 .. 32"), std::string::npos);
  EXPECT_NE(error_of(with("fft_size: 64", "fft_size: 63")).find("stft.fft_size: must be even"), std::string::npos);
  EXPECT_NE(error_of(with("window: hann", "window: hamming")).find("only 'hann'"), std::string::npos);
  EXPECT_NE(error_of(with("power: float32-le", "power: float64-be")).find("only 'float32-le'"), std::string::npos);
  EXPECT_NE(error_of(with("sample_rate_hz: 44100", "sample_rate_hz: -1")).find("sample_rate_hz"), std::string::npos);
  EXPECT_NE(error_of(with("freq_hz: [440, ", "freq_hz: [30000, ")).find("modes.freq_hz[0]: must lie between 0 and Nyquist"),
            std::string::npos);
  EXPECT_NE(error_of(with("amp: [0.25, ", "amp: [")).find("modes.amp: holds 1 values, modes.freq_hz 2"),
            std::string::npos);
  EXPECT_NE(error_of(with("decay_per_s: [3.5", "decay_per_s: [-3.5")).find("modes.decay_per_s[0]: must be >= 0"),
            std::string::npos);
  const std::string located = error_of(with("frames: 7", "frames: seven"));
  EXPECT_EQ(located.rfind("wood.residual.msr:", 0), 0u) << located;
  EXPECT_NE(located.find("frames"), std::string::npos) << located;
}

TEST(ResidualFile, BrokenPayloadsNameFrameAndBin) {
  const std::string good = residual_file_bytes(small_residual());
  EXPECT_EQ(error_of(good.substr(0, good.size() - 3)),
            "wood.residual.msr: payload: 921 bytes after the header, but frames x bins = 7 x 33 float32 need 924 "
            "(cut off?)");
  EXPECT_NE(error_of(good + "x").find("payload: 925 bytes"), std::string::npos);
  std::string negative = good;
  const float minus = -1.0f, nan = std::numeric_limits<float>::quiet_NaN();
  const std::size_t offset = good.find("\n...\n") + 5;
  std::memcpy(negative.data() + offset + 4 * (2 * 33 + 4), &minus, 4);
  EXPECT_EQ(error_of(negative), "wood.residual.msr: payload: frame 2, bin 4 (byte " +
                                    std::to_string(offset + 4 * 70) + ") holds -1, not a power (finite, >= 0)");
  std::string not_a_number = good;
  std::memcpy(not_a_number.data() + offset, &nan, 4);
  EXPECT_NE(error_of(not_a_number).find("frame 0, bin 0"), std::string::npos);
}

TEST(ResidualFile, NothingIsWrittenForAnInvalidResidual) {
  test::TempDir dir;
  const std::string path = dir.write("wood.residual.msr", "before");
  ResidualSpectrogram r = small_residual();
  r.modes.clear();
  EXPECT_THROW(write_residual_file(path, r), std::invalid_argument);
  r = small_residual();
  r.power.pop_back();
  EXPECT_THROW(write_residual_file(path, r), std::invalid_argument);
  r = small_residual();
  r.power[3] = -0.5f;
  EXPECT_THROW(write_residual_file(path, r), std::invalid_argument);
  EXPECT_EQ(test::count_lines(residual_file_bytes(small_residual())) > 5, true);
  std::ifstream in(path);
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "before");
  EXPECT_THROW(write_residual_file(dir.file("no/such/folder/x.msr"), small_residual()), InputError);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), std::filesystem::directory_iterator{}), 1);
}

TEST(ResidualFile, OnlyRegularFilesOfBoundedSizeAreRead) {
  EXPECT_THROW(read_residual_file("/dev/zero"), InputError);
  test::TempDir dir;
  EXPECT_THROW(read_residual_file(dir.file("missing.msr")), InputError);
}
