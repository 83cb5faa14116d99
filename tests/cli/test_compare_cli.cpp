// `modalstudy compare` end to end: identical recordings score 0 (and Pi_MRP -1), a level or frequency
// change scores more, --metric picks one metric, --plot writes the three loudness pictures; bad input
// (silent, clipped, not audio, missing, another sample rate) exits 2 with one line naming the file
// and writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>

#include "synthesis/audio_file.hpp"
#include "synthesis/reference_renderer.hpp"

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int code;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// An impact with a short silent lead-in and a little noise, as a recording has.
std::vector<float> impact(double freq_scale, double gain, double fs = 44100.0, double seconds = 1.0) {
  ms::ModalModel m;
  m.modes = {{523.0 * freq_scale, 4.0, 0.4, 0.0}, {1870.0 * freq_scale, 25.0, 0.2, 0.0},
             {4350.0 * freq_scale, 60.0, 0.1, 0.0}};
  const std::size_t lead = std::size_t(0.01 * fs);
  const auto y = ms::render_reference(m, {}, fs, std::size_t(seconds * fs));
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 1e-5);
  std::vector<float> x(lead + y.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = float(noise(rng) + (i >= lead ? gain * y[i - lead] : 0.0));
  return x;
}

class CompareCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ms_compare_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliRun run(const std::string& args) {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string cmd = std::string(MODALSTUDY_BIN) + " " + args + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    return {WEXITSTATUS(status), slurp(out), slurp(err)};
  }

  fs::path write(const std::string& name, const std::vector<float>& x, double fs = 44100.0) {
    ms::Audio a;
    a.sample_rate_hz = fs;
    a.samples = x;
    const fs::path p = dir_ / name;
    ms::write_wav(p.string(), a, ms::SampleFormat::float32);
    return p;
  }

  nlohmann::json compare_json(const fs::path& a, const fs::path& b, const std::string& extra = "") {
    const CliRun r = run("compare " + a.string() + " " + b.string() + " --json " + extra);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }

  // Bad input: exit 2, exactly one stderr line naming `named` and saying `why`, nothing written.
  void expect_rejected(const fs::path& a, const fs::path& b, const fs::path& named, const std::string& why) {
    const fs::path plots = dir_ / "plots";
    const CliRun r = run("compare " + a.string() + " " + b.string() + " --plot " + plots.string());
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(named.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(plots));
  }

  fs::path dir_;
};

}  // namespace

TEST_F(CompareCli, IdenticalRecordingsScoreZero) {
  const fs::path a = write("a.wav", impact(1.0, 1.0)), b = write("b.wav", impact(1.0, 1.0));
  const nlohmann::json j = compare_json(a, b);
  EXPECT_EQ(j["image"]["psycho"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["feature"]["mrp"].get<double>(), -1.0);
  EXPECT_EQ(j["hybrid"].get<double>(), 0.0);
  EXPECT_EQ(j["feature"]["modes"]["a"].get<int>(), 3);
  EXPECT_EQ(j["image"]["bands"].get<int>(), 26);
  EXPECT_EQ(j["sample_rate"].get<double>(), 44100.0);
  EXPECT_NEAR(j["onset_s"]["a"].get<double>(), 0.01, 0.001);
}

TEST_F(CompareCli, LevelAndFrequencyChangesScoreHigher) {
  const fs::path a = write("a.wav", impact(1.0, 1.0));
  const fs::path quieter = write("quieter.wav", impact(1.0, 0.5));
  const fs::path much_quieter = write("much_quieter.wav", impact(1.0, 0.25));
  const fs::path higher = write("higher.wav", impact(1.04, 1.0));
  const double p2 = compare_json(a, quieter, "--metric image")["image"]["psycho"].get<double>();
  const double p4 = compare_json(a, much_quieter, "--metric image")["image"]["psycho"].get<double>();
  EXPECT_GT(p2, 0.0);
  EXPECT_GT(p4, p2);
  // A level change leaves the modes where they were: the match stays near perfect (the quieter
  // recording's extra weak modes near the true ones pull the per-point means down a little); 4 % higher
  // modes lie ~1 point-distance away and match far worse.
  const double mrp_quieter = compare_json(a, quieter, "--metric feature")["feature"]["mrp"].get<double>();
  EXPECT_LT(mrp_quieter, -0.9);
  const nlohmann::json h = compare_json(a, higher);
  EXPECT_GT(h["feature"]["mrp"].get<double>(), -0.8);
  EXPECT_GT(h["image"]["psycho"].get<double>(), 0.0);
  EXPECT_NEAR(h["hybrid"].get<double>(), h["image"]["psycho"].get<double>() / -h["feature"]["mrp"].get<double>(),
              1e-9 * h["hybrid"].get<double>());
}

TEST_F(CompareCli, MetricOptionSelectsOneAndTextOutputNamesThem) {
  const fs::path a = write("a.wav", impact(1.0, 1.0)), b = write("b.wav", impact(1.0, 0.5));
  const nlohmann::json image = compare_json(a, b, "--metric image");
  EXPECT_TRUE(image.contains("image"));
  EXPECT_FALSE(image.contains("feature"));
  EXPECT_FALSE(image.contains("hybrid"));
  const nlohmann::json feature = compare_json(a, b, "--metric feature");
  EXPECT_FALSE(feature.contains("image"));
  EXPECT_TRUE(feature.contains("feature"));
  const CliRun text = run("compare " + a.string() + " " + b.string());
  EXPECT_EQ(text.code, 0) << text.err;
  for (const char* what : {"Pi_psycho", "Pi_MRP", "Pi_hybrid", "70 dB SPL"})
    EXPECT_NE(text.out.find(what), std::string::npos) << what << "\n" << text.out;
  EXPECT_NE(run("compare " + a.string() + " " + b.string() + " --metric nonsense").code, 0);
}

TEST_F(CompareCli, PlotWritesTheThreeLoudnessPictures) {
  const fs::path a = write("a.wav", impact(1.0, 1.0)), b = write("b.wav", impact(1.03, 0.7));
  const fs::path plots = dir_ / "pictures";
  const CliRun r = run("compare " + a.string() + " " + b.string() + " --metric image --plot " + plots.string());
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"loudness_a.png", "loudness_b.png", "loudness_difference.png"}) {
    const std::string png = slurp(plots / name);
    ASSERT_GT(png.size(), 1000u) << name;
    EXPECT_EQ(png.substr(1, 3), "PNG") << name;
  }
  // --plot naming a file is refused before anything is done.
  const CliRun bad = run("compare " + a.string() + " " + b.string() + " --plot " + a.string());
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--plot must be a folder"), std::string::npos) << bad.err;
}

TEST_F(CompareCli, BadRecordingsAreRefusedByName) {
  const fs::path good = write("good.wav", impact(1.0, 1.0));
  const fs::path silent = write("silent.wav", std::vector<float>(44100, 0.0f));
  std::vector<float> clipped = impact(1.0, 1.0);
  for (float& v : clipped) v = std::clamp(4.0f * v, -1.0f, 1.0f);
  const fs::path clip = write("clipped.wav", clipped);
  const fs::path text = dir_ / "notes.wav";
  std::ofstream(text) << "this is not audio\n";
  const fs::path other_rate = write("48k.wav", impact(1.0, 1.0, 48000.0), 48000.0);
  expect_rejected(good, silent, silent, "silent");
  expect_rejected(silent, good, silent, "silent");
  expect_rejected(good, clip, clip, "clipped");
  expect_rejected(text, good, text, "");
  expect_rejected(good, dir_ / "missing.wav", dir_ / "missing.wav", "");
  expect_rejected(good, other_rate, other_rate, "sample rate 48000 Hz differs from 44100 Hz");
}
