// `modalstudy estimate` end to end: a rendered glass bar estimated on the bar's parameter set (of
// another material) gives glass back, the JSON has the keys, -o writes a material file that
// reads back, --report writes the pictures as PNG and SVG; bad input (silent, clipped, unreadable,
// noise only, too few modes matched, a bad object file) exits 2 with one line and writes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/material.hpp"
#include "synthesis/material_file.hpp"
#include "synthesis/reference_renderer.hpp"

namespace fs = std::filesystem;
using ms::test::run_cli;
using ms::test::TempDir;

namespace {

const std::string kBar = MODALSTUDY_SOURCE_DIR "/stimuli/bar/ren-wood.yaml";

std::string write_wav(const TempDir& dir, const std::string& name, const std::vector<float>& x) {
  ms::Audio a;
  a.sample_rate_hz = 44100;
  a.samples = x;
  ms::write_wav(dir.file(name), a, ms::SampleFormat::float32);
  return dir.file(name);
}

// Bad input: exit 2, one stderr line naming `named` and saying `why`, neither -o nor --report written.
void expect_rejected(const TempDir& dir, const std::string& recording, const std::string& object,
                     const std::string& named, const std::string& why) {
  const auto r = run_cli("estimate " + recording + " --object " + object + " -o " + dir.file("m.yaml") +
                             " --report " + dir.file("report"),
                         dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(named), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
  EXPECT_EQ(ms::test::count_lines(r.err), 1u) << r.err;
  EXPECT_FALSE(fs::exists(dir.file("m.yaml")));
  EXPECT_FALSE(fs::exists(dir.file("report")));
}

TEST(EstimateCli, AGlassBarGivesGlassBackWithTheMaterialFileAndTheReport) {
  TempDir dir;
  const auto synth = run_cli("synth " MODALSTUDY_SOURCE_DIR "/stimuli/bar/ren-glass.yaml -o " + dir.file("glass.wav"), dir);
  ASSERT_EQ(synth.exit_code, 0) << synth.err;
  const auto r = run_cli("estimate " + dir.file("glass.wav") + " --object " + kBar + " --json -o " +
                             dir.file("glass.yaml") + " --report " + dir.file("report"),
                         dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const ms::Material& glass = *ms::find_material("ren2013/glass");
  EXPECT_NEAR(j["material"]["alpha"].get<double>() / glass.rayleigh.alpha1, 1.0, 0.10);
  EXPECT_NEAR(j["material"]["beta"].get<double>() / glass.rayleigh.alpha2, 1.0, 0.10);
  EXPECT_NEAR(j["material"]["gamma"].get<double>() / glass.specific_modulus_m2_s2, 1.0, 0.02);
  EXPECT_GT(j["material"]["sigma"].get<double>(), 0.0);
  for (const char* k : {"image", "feature", "hybrid"}) EXPECT_TRUE(j["metric"].contains(k)) << k;
  // The strike's contact is fitted; both sets strike with a 0.5 ms raised cosine.
  EXPECT_NEAR(j["contact_s"].get<double>() / 0.5e-3, 1.0, 0.25);
  EXPECT_GE(j["starts"].get<int>(), 1);
  EXPECT_GT(j["iterations"].get<int>(), 0);
  EXPECT_GT(j["seconds"].get<double>(), 0.0);
  EXPECT_GE(j["matched_modes"].get<int>(), 3);
  const ms::Material m = ms::read_material_file(dir.file("glass.yaml"));
  EXPECT_EQ(m.rayleigh.alpha1, j["material"]["alpha"].get<double>());
  EXPECT_EQ(m.specific_modulus_m2_s2, j["material"]["gamma"].get<double>());
  for (const char* p : {"spectrogram_recording", "spectrogram_synthesis", "damping", "feature_matches"})
    for (const char* ext : {".png", ".svg"}) EXPECT_GT(fs::file_size(dir.file(std::string("report/") + p + ext)), 0u) << p << ext;
  EXPECT_TRUE(fs::exists(dir.file("report/estimate.json")));
}

TEST(EstimateCli, BadRecordingsAndObjectsAreOneLineAndWriteNothing) {
  TempDir dir;
  const std::size_t n = 44100;
  expect_rejected(dir, write_wav(dir, "silent.wav", std::vector<float>(n, 0.0f)), kBar, "silent.wav", "silent");
  std::vector<float> clipped(n);
  for (std::size_t i = 0; i < n; ++i) clipped[i] = std::sin(0.05 * double(i)) > 0 ? 1.0f : -1.0f;
  expect_rejected(dir, write_wav(dir, "clipped.wav", clipped), kBar, "clipped.wav", "clip");
  expect_rejected(dir, dir.write("text.wav", "not audio\n"), kBar, "text.wav", "");
  std::mt19937 rng(5);
  std::normal_distribution<float> noise(0.0f, 0.01f);
  std::vector<float> hiss(n);
  for (float& v : hiss) v = noise(rng);
  expect_rejected(dir, write_wav(dir, "noise.wav", hiss), kBar, "noise.wav", "");
  // Two modes far from any the bar can make together: fewer than 3 matched.
  ms::ModalModel two;
  two.modes = {{1000.0, 3.0, 0.3, 0.0}, {1013.0, 40.0, 0.3, 0.0}};
  const auto y = ms::render_reference(two, {}, 44100.0, n);
  expect_rejected(dir, write_wav(dir, "two.wav", std::vector<float>(y.begin(), y.end())), kBar, "two.wav", "");
  const std::string good = write_wav(dir, "good.wav", std::vector<float>(y.begin(), y.end()));
  expect_rejected(dir, good, dir.file("missing.yaml"), "missing.yaml", "");
  expect_rejected(dir, good, dir.write("bad.yaml", "object: {type: bar, length_m: -1}\n"), "bad.yaml", "");
}

}  // namespace
