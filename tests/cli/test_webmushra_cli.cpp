// `modalstudy protocol import-webmushra` and `modalstudy export --format webmushra` as a user runs them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"

using namespace ms;

namespace {

void write_tone(const test::TempDir& dir, const std::string& rel) {
  Audio a;
  a.sample_rate_hz = 44100;
  for (int i = 0; i < 4410; ++i) a.samples.push_back(float(0.3 * std::sin(0.07 * i) * std::exp(-i / 700.0)));
  std::filesystem::create_directories(std::filesystem::path(dir.file(rel)).parent_path());
  write_wav(dir.file(rel), a, SampleFormat::pcm16);
}

}  // namespace

TEST(WebMushraCli, ImportWritesAValidProtocolAndNotesOnStderr) {
  test::TempDir dir;
  write_tone(dir, "configs/a/ref.wav");
  write_tone(dir, "configs/a/c1.wav");
  const std::string config = dir.write(
      "configs/t.yaml",
      "testname: T\ntestId: t1\npages:\n  - type: mushra\n    id: m\n    showWaveform: true\n"
      "    reference: configs/a/ref.wav\n    createAnchor35: true\n    createAnchor70: true\n"
      "    stimuli: {C1: configs/a/c1.wav}\n");
  const auto r = test::run_cli("protocol import-webmushra " + config + " -o " + dir.file("p.yaml"), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("note: " + config + ":6:19: pages[0].showWaveform: not carried over"), std::string::npos) << r.err;
  const auto check = test::run_cli("protocol check " + dir.file("p.yaml"), dir);
  EXPECT_EQ(check.exit_code, 0) << check.err;
  const auto run = test::run_cli("protocol schedule " + dir.file("p.yaml") + " --participant X", dir);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("m #0 mushra"), std::string::npos) << run.out;
}

TEST(WebMushraCli, BadConfigExitsTwoWithOneLineAndWritesNothing) {
  test::TempDir dir;
  const std::string config =
      dir.write("configs/t.yaml", "testId: t1\npages:\n  - {type: mushra, id: m, reference: configs/none.wav, "
                                  "stimuli: {C1: configs/none.wav}}\n");
  const auto r = test::run_cli("protocol import-webmushra " + config + " -o " + dir.file("p.yaml"), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find(config + ":3:"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("p.yaml")));
}

TEST(WebMushraCli, ExportFormatIsCheckedAndAMissingStoreWritesNothing) {
  test::TempDir dir;
  auto r = test::run_cli("export " + dir.file("none.sqlite") + " -o " + dir.file("out") + " --format webmushra", dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(dir.file("out")));
  r = test::run_cli("export " + dir.file("none.sqlite") + " -o " + dir.file("out") + " --format beaqle", dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("beaqle"), std::string::npos) << r.err;
}
