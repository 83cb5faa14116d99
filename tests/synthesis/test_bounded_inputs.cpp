// Inputs that cannot hang, blow up or escape: every file is read through one bounded reader (regular
// files only, a size cap per kind), every path a parameter set names is confined, the one YAML reader
// refuses duplicate keys and alias bombs, doublets cannot make negative frequencies, and a cut-off
// WAV is refused instead of analysed.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/bounded_file.hpp"
#include "synthesis/effects.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/modes_csv.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/path_confinement.hpp"
#include "synthesis/stimulus.hpp"
#include "synthesis/yaml_reader.hpp"

using namespace ms;
namespace fs = std::filesystem;

namespace {

// The message of the InputError `fn` throws ("" when it throws none).
template <class Fn>
std::string error_of(Fn fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Runs fn and returns its wall time in seconds.
template <class Fn>
double seconds(Fn fn) {
  const auto t0 = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

const char* kOneMode = "duration_s: 0.1\nmodes: [{freq_hz: 440, decay_per_s: 3, amp: 1}]\n";

std::string fifo(const test::TempDir& dir, const std::string& name) {
  const std::string path = dir.file(name);
  EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0) << std::strerror(errno);
  return path;
}

// A 16-bit mono RIFF WAV of `frames` frames of a decaying 440 Hz tone; `declared` overrides the data
// chunk's size field, `keep` cuts the file after that many bytes.
std::string wav_bytes(std::size_t frames, std::int64_t declared = -1, std::size_t keep = SIZE_MAX) {
  std::string b;
  auto u32 = [&](std::uint32_t v) { for (int i = 0; i < 4; ++i) b.push_back(char(v >> (8 * i) & 0xFF)); };
  auto u16 = [&](std::uint16_t v) { for (int i = 0; i < 2; ++i) b.push_back(char(v >> (8 * i) & 0xFF)); };
  const std::uint32_t data = std::uint32_t(frames * 2);
  b += "RIFF";
  u32(36 + data);
  b += "WAVEfmt ";
  u32(16);
  u16(1);
  u16(1);
  u32(44100);
  u32(88200);
  u16(2);
  u16(16);
  b += "data";
  u32(declared >= 0 ? std::uint32_t(declared) : data);
  for (std::size_t n = 0; n < frames; ++n)
    u16(std::uint16_t(std::int16_t(20000 * std::exp(-5.0 * n / 44100) * std::sin(2 * std::numbers::pi * 440 * n / 44100))));
  if (keep < b.size()) b.resize(keep);
  return b;
}

}  // namespace

TEST(BoundedFile, RefusesFifoDeviceFolderWithoutBlocking) {
  test::TempDir dir;
  const std::string pipe = fifo(dir, "pipe");  // no writer: a plain open() would block forever
  double t = seconds([&] {
    EXPECT_NE(error_of([&] { read_bounded_file(pipe, kYamlFileLimit); }).find("is a FIFO"), std::string::npos);
  });
  EXPECT_LT(t, 1.0);
  EXPECT_NE(error_of([&] { read_bounded_file("/dev/zero", kCsvFileLimit); }).find("/dev/zero: is a device"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_bounded_file(dir.path().string(), kCsvFileLimit); }).find("is a folder"),
            std::string::npos);
  EXPECT_NE(error_of([&] { read_bounded_file(dir.file("none"), kCsvFileLimit); }).find("no such file"),
            std::string::npos);
  EXPECT_EQ(read_bounded_file(dir.write("a.txt", "abc"), kCsvFileLimit), "abc");
}

TEST(BoundedFile, RefusesFilesOverTheCapBeforeReadingThem) {
  test::TempDir dir;
  const std::string big = dir.file("big.yaml");
  { std::ofstream(big) << "x: 1\n"; }
  fs::resize_file(big, kYamlFileLimit.max_bytes + 1);  // sparse: no 16 MiB written
  const std::string e = error_of([&] { read_bounded_file(big, kYamlFileLimit); });
  EXPECT_NE(e.find("more than the 16 MiB a YAML file may have"), std::string::npos) << e;
  fs::resize_file(big, kYamlFileLimit.max_bytes);
  EXPECT_EQ(read_bounded_file(big, kYamlFileLimit).size(), kYamlFileLimit.max_bytes);
}

TEST(BoundedFile, ProcFilesOfUnknownSizeAreCappedWhileReading) {
  // /proc files report size 0; the cap holds while reading.
  const std::string e = error_of([] { read_bounded_file("/proc/self/maps", FileLimit{"test file", 16}); });
  EXPECT_NE(e.find("more than the 16 bytes a test file may have"), std::string::npos) << e;
}

TEST(BoundedInputs, ParameterSetAndItsModesCsvMustBeRegularFiles) {
  test::TempDir dir;
  const std::string pipe = fifo(dir, "m.csv");
  const std::string set = dir.write("s.yaml", "duration_s: 0.1\nmodes: m.csv\n");
  std::string e;
  const double t = seconds([&] { e = error_of([&] { load_paramset(set); }); });
  EXPECT_LT(t, 1.0);
  EXPECT_NE(e.find("s.yaml:2:8: modes: cannot use"), std::string::npos) << e;
  EXPECT_NE(e.find("is a FIFO"), std::string::npos) << e;
  e = error_of([&] { load_paramset(fifo(dir, "set.yaml")); });
  EXPECT_NE(e.find("set.yaml: is a FIFO"), std::string::npos) << e;
  e = error_of([&] { load_paramset("/dev/zero"); });
  EXPECT_NE(e.find("/dev/zero: is a device"), std::string::npos) << e;
  // /dev/zero as the CSV: outside the set's folder, and a device even when allowed.
  const std::string zero = dir.write("z.yaml", "duration_s: 0.1\nmodes: /dev/zero\n");
  const Confinement anywhere = Confinement::anywhere();
  e = error_of([&] { load_paramset(zero, {}, &anywhere); });
  EXPECT_NE(e.find("is a device"), std::string::npos) << e;
}

TEST(BoundedInputs, AudioMustBeARegularFile) {
  test::TempDir dir;
  const std::string pipe = fifo(dir, "a.wav");
  std::string e;
  const double t = seconds([&] { e = error_of([&] { read_audio(pipe); }); });
  EXPECT_LT(t, 1.0);
  EXPECT_NE(e.find("a.wav: is a FIFO"), std::string::npos) << e;
  EXPECT_NE(error_of([] { read_audio("/dev/zero"); }).find("is a device"), std::string::npos);
  EXPECT_NE(error_of([&] { read_audio(dir.write("t.wav", "just text\n")); }).find("not a readable audio file"),
            std::string::npos);
}

TEST(Confinement, ModesCsvOutsideTheSetsFolderIsRefused) {
  test::TempDir dir;
  dir.write("outside/m.csv", "freq_hz,decay_per_s,amp\n440,3,1\n");
  dir.write("sets/in/m.csv", "freq_hz,decay_per_s,amp\n440,3,1\n");
  const std::string up = dir.write("sets/in/up.yaml", "duration_s: 0.1\nmodes: ../../outside/m.csv\n");
  std::string e = error_of([&] { load_paramset(up); });
  EXPECT_NE(e.find("up.yaml:2:8: modes: path '../../outside/m.csv' is outside the parameter set's folder"),
            std::string::npos) << e;
  e = error_of([&] { load_paramset(dir.write("sets/in/etc.yaml", "duration_s: 0.1\nmodes: /etc/passwd\n")); });
  EXPECT_NE(e.find("etc.yaml:2:8: modes: path '/etc/passwd' is outside"), std::string::npos) << e;
  EXPECT_EQ(e.find("root"), std::string::npos) << "no content of the file may leak: " << e;
  // A symbolic link inside the folder that leads out is outside too.
  fs::create_symlink(dir.path() / "outside/m.csv", dir.path() / "sets/in/link.csv");
  e = error_of([&] { load_paramset(dir.write("sets/in/link.yaml", "duration_s: 0.1\nmodes: link.csv\n")); });
  EXPECT_NE(e.find("path 'link.csv' is outside"), std::string::npos) << e;
  // Inside: fine; the same escape with an explicit permission: fine.
  EXPECT_EQ(load_paramset(dir.write("sets/in/ok.yaml", "duration_s: 0.1\nmodes: m.csv\n")).model.modes.size(), 1u);
  const Confinement anywhere = Confinement::anywhere();
  EXPECT_EQ(load_paramset(up, {}, &anywhere).model.modes.size(), 1u);
  // --set cannot move the CSV out either.
  e = error_of([&] { load_paramset(dir.file("sets/in/ok.yaml"), {"modes=../../outside/m.csv"}); });
  EXPECT_NE(e.find("is outside"), std::string::npos) << e;
}

TEST(Confinement, AStimuliFolderIsOneProject) {
  test::TempDir dir;
  dir.write("stimuli/shared/m.csv", "freq_hz,decay_per_s,amp\n440,3,1\n");
  const std::string set = dir.write("stimuli/bar/s.yaml", "duration_s: 0.1\nmodes: ../shared/m.csv\n");
  EXPECT_EQ(load_paramset(set).model.modes.size(), 1u);
  const Confinement c = paramset_confinement(dir.file("stimuli/bar"));
  EXPECT_TRUE(c.allows(dir.path() / "stimuli/shared/m.csv"));
  EXPECT_FALSE(c.allows(dir.path() / "elsewhere.csv"));
  EXPECT_FALSE(c.allows(dir.path() / "stimuli/../elsewhere.csv"));
}

TEST(YamlDuplicates, ADuplicateKeyNamesBothLines) {
  const std::string e = error_of([] {
    parse_paramset("duration_s: 0.1\nmodes: [{freq_hz: 440, decay_per_s: 3, amp: 1}]\nduration_s: 5\n", "set.yaml", ".");
  });
  EXPECT_EQ(e, "set.yaml:3:1: duplicate key 'duration_s' (first at line 1, column 1)");
  const std::string nested = error_of([] {
    parse_paramset("duration_s: 0.1\nmodes:\n  - {freq_hz: 440, decay_per_s: 3, amp: 1, amp: 2}\n", "set.yaml", ".");
  });
  EXPECT_EQ(nested, "set.yaml:3:44: duplicate key 'amp' (first at line 3, column 36)");
}

TEST(YamlDuplicates, AliasBombsAndCyclesAreRefusedQuickly) {
  // Nine levels of ten aliases each expand to 10^9 values.
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 10; ++i) {
    bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) bomb += std::string(k ? ", " : "") + "*a" + std::to_string(i - 1);
    bomb += "]\n";
  }
  std::string e;
  const double t = seconds([&] { e = error_of([&] { YamlReader("b.yaml").load(bomb); }); });
  EXPECT_LT(t, 5.0);
  EXPECT_NE(e.find("expands to more than 4000000 values through aliases"), std::string::npos) << e;
  // Aliases that stay small are fine.
  EXPECT_TRUE(YamlReader("ok.yaml").load("a: &x [1, 2]\nb: *x\n")["b"].IsSequence());
}

TEST(Doublets, SplitsThatWouldMakeNegativeFrequenciesAreRefused) {
  const std::string base = std::string(kOneMode) + "effects: {doublets: {";
  std::string e = error_of([&] { parse_paramset(base + "split_rel: 2}}\n", "s.yaml", "."); });
  EXPECT_NE(e.find("s.yaml:3:33: effects.doublets.split_rel: must lie in (0, 1)"), std::string::npos) << e;
  e = error_of([&] { parse_paramset(base + "split_rel: 1}}\n", "s.yaml", "."); });
  EXPECT_NE(e.find("must lie in (0, 1)"), std::string::npos) << e;
  e = error_of([&] { parse_paramset(base + "split_hz: 900}}\n", "s.yaml", "."); });
  EXPECT_NE(e.find("s.yaml:3:32: effects.doublets.split_hz: must be less than the frequency of every mode it splits"),
            std::string::npos) << e;
  const ParamSet ok = parse_paramset(base + "split_rel: 0.5}}\n", "s.yaml", ".");
  ASSERT_EQ(ok.model.modes.size(), 2u);
  EXPECT_DOUBLE_EQ(ok.model.modes[0].freq_hz, 440 * 0.75);
  EXPECT_DOUBLE_EQ(ok.model.modes[1].freq_hz, 440 * 1.25);
  ModalModel m;
  m.modes = {Mode{100, 1, 1, 0}};
  EXPECT_THROW(apply_doublets(m, Doublets{2.5, 0, 0.5, 1}, {}), std::invalid_argument);
}

TEST(Doublets, AContactRenderStaysBoundedByModesTimesSamples) {
  // The former hang: a contact excitation and a split that put modes far below 0 Hz.
  const std::string base = "duration_s: 0.5\nmodes: [{freq_hz: 440, decay_per_s: 3, amp: 1}]\n"
                           "excitation: {type: hertz, contact_s: 0.05}\neffects: {doublets: {split_rel: 100000}}\n";
  EXPECT_NE(error_of([&] { parse_paramset(base, "s.yaml", "."); }).find("must lie in (0, 1)"), std::string::npos);
  // A mode at a negative frequency that reaches the renderer some other way is dropped, not rendered.
  ParamSet p = parse_paramset("duration_s: 0.5\nmodes: [{freq_hz: 440, decay_per_s: 3, amp: 1}]\n"
                              "excitation: {type: hertz, contact_s: 0.05}\n", "s.yaml", ".");
  p.model.modes.push_back(Mode{-2.2e7, 3, 1, 0});
  RenderedStimulus r;
  const double t = seconds([&] { r = render_stimulus(p); });
  EXPECT_EQ(r.modes_rendered, 1u);
  EXPECT_LT(t, 2.0);
}

TEST(TruncatedWav, CutOffOrUnfinishedHeadersAreRefusedPrecisely) {
  test::TempDir dir;
  const std::string full = wav_bytes(44100);
  EXPECT_EQ(read_audio(dir.write("full.wav", full)).frames(), 44100u);
  std::string e = error_of([&] { read_audio(dir.write("half.wav", full.substr(0, full.size() / 2))); });
  EXPECT_NE(e.find("half.wav: truncated: the WAV header declares 88200 bytes of samples but only 44078 follow"),
            std::string::npos) << e;
  e = error_of([&] { read_audio(dir.write("cut40ms.wav", full.substr(0, full.size() - 1764 * 2))); });
  EXPECT_NE(e.find("declares 88200 bytes of samples but only 84672 follow"), std::string::npos) << e;
  e = error_of([&] { read_audio(dir.write("huge.wav", wav_bytes(44100, 0xFFFFFFF0))); });
  EXPECT_NE(e.find("declares 4294967280 bytes of samples but only 88200 follow"), std::string::npos) << e;
  e = error_of([&] { read_audio(dir.write("zero.wav", wav_bytes(44100, 0))); });
  EXPECT_NE(e.find("declares no samples but 88200 bytes follow"), std::string::npos) << e;
}

TEST(OutputStage, APeakAboveFullScaleNamesTheFormatKey) {
  test::TempDir dir;
  const ParamSet p = parse_paramset("duration_s: 0.1\nmodes: [{freq_hz: 440, decay_per_s: 3, amp: 4}]\n"
                                    "level: {normalize: none}\noutput: {format: pcm16}\n", "s.yaml", ".");
  const RenderedStimulus r = render_stimulus(p);
  const std::string e = error_of([&] { check_writable(p, r.audio, p.format_where); });
  EXPECT_NE(e.find("s.yaml:4:18: output.format: pcm16 cannot hold the rendered peak of +12.0 dBFS"), std::string::npos)
      << e;
  ParamSet f = p;
  f.format = SampleFormat::float32;
  EXPECT_EQ(error_of([&] { check_writable(f, r.audio, f.format_where); }), "");
}

TEST(StudyIds, OnlyIdentifiersNameFiles) {
  for (const char* ok : {"demo", "vase-pruning", "ren2013_materials", "v1.2"}) EXPECT_TRUE(is_identifier(ok)) << ok;
  for (const char* bad : {"", "../../../x", "a/b", ".hidden", "-x", "a b", "x\\y", "..", "\xc3\xa9t\xc3\xa9"})
    EXPECT_FALSE(is_identifier(bad)) << bad;
  EXPECT_FALSE(is_identifier(std::string(65, 'a')));
}

TEST(ModesCsvMessages, RaggedRowsAndMissingColumnsNameAColumn) {
  EXPECT_EQ(error_of([] { parse_modes_csv("freq_hz,decay_per_s,amp\n440,3\n", "m.csv"); }),
            "m.csv:2:5: expected 3 cells, got 2 (no 'amp')");
  EXPECT_EQ(error_of([] { parse_modes_csv("freq_hz,decay_per_s,amp\n440,3,1,9\n", "m.csv"); }),
            "m.csv:2:9: expected 3 cells, got 4");
  EXPECT_EQ(error_of([] { parse_modes_csv("freq_hz,amp\n440,1\n", "m.csv"); }),
            "m.csv:1:1: missing column 'decay_per_s' (need freq_hz,decay_per_s,amp)");
}
