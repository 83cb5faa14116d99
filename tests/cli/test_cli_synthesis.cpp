// The command line end to end: synth, stimuli build (incremental, manifest), bench synth, and bad
// input ending in one line, exit code 2 and no output file.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"

using namespace ms;
namespace fs = std::filesystem;

namespace {
const char* kMinimal = R"(sample_rate: 44100
duration_s: 0.5
modes:
  - {freq_hz: 440.0, decay_per_s: 3.0, amp: 1.0}
excitation: {type: impulse}
level: {normalize: none}
)";
}

TEST(CliSynth, RendersWavAndJson) {
  test::TempDir dir;
  const std::string set = dir.write("s.yaml", kMinimal);
  const auto r = test::run_cli("synth " + set + " -o " + dir.file("out.wav") + " --json --set duration_s=0.25 "
                               "--modes-out " + dir.file("modes.csv"), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 11025);
  EXPECT_EQ(j["modes"], 1);
  EXPECT_EQ(j["recipe_hash"].get<std::string>().size(), 64u);
  const Audio a = read_audio(dir.file("out.wav"));
  EXPECT_EQ(a.frames(), 11025u);
  EXPECT_NEAR(a.samples[100], std::exp(-3.0 * 100 / 44100) * std::sin(2 * std::numbers::pi * 440 * 100 / 44100), 1e-6);
  std::ifstream csv(dir.file("modes.csv"));
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "freq_hz,decay_per_s,amp,phase_rad\r");  // RFC 4180 CRLF
}

TEST(CliSynth, BadInputIsOneLineExit2AndNoFile) {
  test::TempDir dir;
  const std::string out = dir.file("out.wav");
  struct Case {
    std::string args, expect;
  } cases[] = {
      {dir.write("a.yaml", "duration_s: 1\nmodes: [{freq_hz: 1, decay_per_s: -1, amp: 1}]\n"), "a.yaml:2:35"},
      {dir.write("b.yaml", "duration_s: 1\nmode: []\n"), "did you mean 'modes'"},
      {dir.write("c.yaml", "duration_s: [\n"), "YAML syntax error"},
      {dir.file("missing.yaml"), "missing.yaml: no such file"},
      {std::string(dir.write("d.yaml", kMinimal)) + " --set duration_s=-1", "--set duration_s"},
      {std::string(dir.write("e.yaml", kMinimal)) + " --format mp3", "--format"},
  };
  for (const Case& c : cases) {
    const auto r = test::run_cli("synth " + c.args + " -o " + out, dir);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
  // Unwritable output path.
  const auto r = test::run_cli("synth " + dir.file("e.yaml") + " -o /nonexistent/dir/x.wav", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/nonexistent/dir/x.wav"), std::string::npos) << r.err;
}

TEST(CliStimuli, BuildIsIncrementalWithManifest) {
  test::TempDir dir;
  dir.write("sets/one.yaml", kMinimal);
  dir.write("sets/sub/two.yaml", std::string(kMinimal) + "description: second\n");
  const std::string sets = dir.file("sets"), out = dir.file("out");
  auto r = test::run_cli("stimuli build " + sets + " -o " + out + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["rendered"], 2);
  EXPECT_EQ(j["reused"], 0);
  EXPECT_TRUE(fs::exists(dir.file("out/one.wav")));
  EXPECT_TRUE(fs::exists(dir.file("out/sub/two.wav")));
  std::ifstream in(dir.file("out/manifest.json"));
  const auto manifest = nlohmann::json::parse(in);
  ASSERT_EQ(manifest["stimuli"].size(), 2u);
  EXPECT_EQ(manifest["stimuli"][0]["sha256"].get<std::string>().size(), 64u);
  // Nothing changed: nothing rendered.
  r = test::run_cli("stimuli build " + sets + " -o " + out + " --json", dir);
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["rendered"], 0);
  EXPECT_EQ(j["reused"], 2);
  // One recipe changes, one output is deleted: exactly those two re-render.
  dir.write("sets/one.yaml", std::string(kMinimal) + "output: {format: pcm24}\n");
  r = test::run_cli("stimuli build " + sets + " -o " + out + " --json", dir);
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["rendered"], 1);
  fs::remove(dir.file("out/sub/two.wav"));
  r = test::run_cli("stimuli build " + sets + " -o " + out + " --json", dir);
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["rendered"], 1);
  EXPECT_EQ(j["reused"], 1);
}

TEST(CliStimuli, ABadSetWritesNothing) {
  test::TempDir dir;
  dir.write("sets/good.yaml", kMinimal);
  dir.write("sets/bad.yaml", "duration_s: 0\nmodes: [{freq_hz: 1, decay_per_s: 1, amp: 1}]\n");
  const auto r = test::run_cli("stimuli build " + dir.file("sets") + " -o " + dir.file("out"), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.yaml:1:13"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("out/good.wav")));
  EXPECT_FALSE(fs::exists(dir.file("out/manifest.json")));
}

TEST(CliBench, SynthJsonShape) {
  test::TempDir dir;
  const auto r = test::run_cli("bench synth --modes 256 --seconds 0.2 --repeats 1 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["modes"], 256);
  EXPECT_EQ(j["seconds"], 0.2);
  EXPECT_EQ(j["sample_rate"], 44100.0);
  EXPECT_EQ(j["threads"], 1);
  EXPECT_GT(j["mode_samples_per_s"].get<double>(), 1e8);
}
