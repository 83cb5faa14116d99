// `modalstudy extract` end to end: a known impact written with write_wav comes back in the CSV and
// JSON; bad recordings (silent, clipped, too short, not audio, missing) exit 2 with one line naming
// the file and leave no output file.
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
#include "synthesis/effects.hpp"
#include "synthesis/reference_renderer.hpp"

namespace fs = std::filesystem;

namespace {

struct CliRun {
  int code;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class ExtractCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ms_extract_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
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

  fs::path write(const std::string& name, const std::vector<float>& x, int channels = 1) {
    ms::Audio a;
    a.sample_rate_hz = 44100.0;
    a.channels = channels;
    a.samples = x;
    const fs::path p = dir_ / name;
    ms::write_wav(p.string(), a, ms::SampleFormat::float32);
    return p;
  }

  // Bad input: exit 2, exactly one stderr line naming the file, no CSV left behind.
  void expect_rejected(const fs::path& wav, const std::string& why) {
    const fs::path csv = dir_ / "features.csv";
    const CliRun r = run("extract " + wav.string() + " -o " + csv.string());
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(wav.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(csv));
  }

  fs::path dir_;
};

std::vector<float> two_mode_impact(double seconds, double lead_s = 0.0) {
  ms::ModalModel m;
  m.modes = {{523.0, 3.0, 0.4, 0.0}, {1870.0, 25.0, 0.2, 0.0}};
  const auto clean = ms::render_reference(m, {}, 44100.0, std::size_t(seconds * 44100.0));
  std::vector<float> x(std::size_t(lead_s * 44100.0), 0.0f);
  for (double v : clean) x.push_back(float(v));
  // Seeded white noise at -80 dB re full scale: the recording's noise floor.
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, 1e-4);
  for (float& v : x) v += float(noise(rng));
  return x;
}

TEST_F(ExtractCli, CsvAndJsonCarryTheModes) {
  const fs::path wav = write("bowl.wav", two_mode_impact(1.0, 0.25));
  const fs::path csv = dir_ / "features.csv";
  const CliRun r = run("extract " + wav.string() + " --json -o " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["sounds"].size(), 1u);
  const auto& s = j["sounds"][0];
  EXPECT_EQ(s["sound"], "bowl");
  EXPECT_DOUBLE_EQ(s["sample_rate"].get<double>(), 44100.0);
  EXPECT_NEAR(s["onset_s"].get<double>(), 0.25, 0.001);
  EXPECT_NEAR(s["noise_floor_db"].get<double>(), -80.0, 1.0);
  ASSERT_EQ(s["modes"].size(), 2u) << r.out;
  EXPECT_NEAR(s["modes"][0]["freq_hz"].get<double>(), 523.0, 0.01);
  EXPECT_NEAR(s["modes"][0]["decay_per_s"].get<double>(), 3.0, 0.03);
  EXPECT_NEAR(s["modes"][0]["amp"].get<double>(), 0.4, 0.004);
  EXPECT_NEAR(s["modes"][1]["freq_hz"].get<double>(), 1870.0, 0.02);
  EXPECT_NEAR(s["modes"][1]["decay_per_s"].get<double>(), 25.0, 0.25);
  EXPECT_NEAR(s["modes"][1]["amp"].get<double>(), 0.2, 0.002);
  // Error bars (Cramer-Rao): tiny at 80 dB SNR, larger for the weaker, faster mode, and the
  // estimates lie within a few of them of the truth.
  for (const char* key : {"freq_sd_hz", "decay_sd_per_s", "amp_sd"})
    for (int k = 0; k < 2; ++k) EXPECT_GT(s["modes"][k][key].get<double>(), 0.0) << key;
  const double f0_sd = s["modes"][0]["freq_sd_hz"].get<double>();
  EXPECT_LT(f0_sd, 1e-3);
  EXPECT_GT(s["modes"][1]["freq_sd_hz"].get<double>(), f0_sd);
  EXPECT_LE(std::abs(s["modes"][0]["freq_hz"].get<double>() - 523.0), 5.0 * f0_sd);
  const std::string text = slurp(csv);
  EXPECT_EQ(text.rfind("sound,freq_hz,decay_per_s,amp\r\n", 0), 0u) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3) << text;
  EXPECT_NE(text.find("\nbowl,523"), std::string::npos) << text;
}

// --errors adds the error bars to the CSV, which fit-damping still reads (by column name).
TEST_F(ExtractCli, ErrorsAddColumnsTheOtherCommandsStillRead) {
  const fs::path wav = write("bowl.wav", two_mode_impact(1.0, 0.25));
  const fs::path csv = dir_ / "features.csv";
  const CliRun r = run("extract " + wav.string() + " --errors -o " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = slurp(csv);
  EXPECT_EQ(text.rfind("sound,freq_hz,decay_per_s,amp,freq_sd_hz,decay_sd_per_s,amp_sd\r\n", 0), 0u) << text;
  ASSERT_EQ(std::count(text.begin(), text.end(), '\n'), 3) << text;
  // Each row: 7 fields, the three error bars positive numbers.
  std::istringstream rows(text);
  std::string line;
  std::getline(rows, line);
  while (std::getline(rows, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    ASSERT_EQ(cells.size(), 7u) << line;
    for (std::size_t k = 4; k < 7; ++k) EXPECT_GT(std::stod(cells[k]), 0.0) << line;
    EXPECT_LT(std::stod(cells[4]), 0.01) << line;  // freq_sd_hz at 80 dB SNR
  }
  const CliRun fit = run("fit-damping " + csv.string() + " --law rayleigh --estimator lsq --json");
  EXPECT_EQ(fit.code, 0) << fit.err;
  // Without a CSV to write, --errors is a mistake, said in one line.
  const CliRun alone = run("extract " + wav.string() + " --errors");
  EXPECT_NE(alone.code, 0);
  EXPECT_NE(alone.err.find("--errors"), std::string::npos) << alone.err;
}

// --thorough adds a second start for the low band; on a clean two-mode sound it changes nothing.
TEST_F(ExtractCli, ThoroughKeepsASimpleSoundsModes) {
  const fs::path wav = write("bowl.wav", two_mode_impact(1.0));
  const CliRun r = run("extract " + wav.string() + " --json --thorough");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto modes = nlohmann::json::parse(r.out)["sounds"][0]["modes"];
  ASSERT_EQ(modes.size(), 2u) << r.out;
  EXPECT_NEAR(modes[0]["freq_hz"].get<double>(), 523.0, 0.01);
  EXPECT_NEAR(modes[1]["decay_per_s"].get<double>(), 25.0, 0.25);
}

// A burst of attack noise (white, 6 ms of 60 dB decay, -20 dB re the strike): by default the fit
// restarts after it (fit_start_s) and the two modes come back with their amplitudes (beside one fast
// pseudo-mode of the burst's last trace: 3 modes); --max-attack-skip-ms 0 fits from the contact on and
// takes the burst for extra modes (11); a value out of range is refused.
TEST_F(ExtractCli, AttackNoiseIsSkippedUnlessTurnedOff) {
  std::vector<float> x = two_mode_impact(1.0);
  ms::add_reverb_and_transient(x, 44100.0, {}, {-20.0, 6.0, 4, true});
  const fs::path wav = write("burst.wav", x);
  const CliRun r = run("extract " + wav.string() + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto s = nlohmann::json::parse(r.out)["sounds"][0];
  EXPECT_GT(s["fit_start_s"].get<double>(), 2e-3);
  ASSERT_GE(s["modes"].size(), 2u) << r.out;
  EXPECT_NEAR(s["modes"][0]["amp"].get<double>(), 0.4, 0.004);
  EXPECT_NEAR(s["modes"][1]["amp"].get<double>(), 0.2, 0.002);
  const CliRun off = run("extract " + wav.string() + " --json --max-attack-skip-ms 0");
  ASSERT_EQ(off.code, 0) << off.err;
  const auto t = nlohmann::json::parse(off.out)["sounds"][0];
  EXPECT_NEAR(t["fit_start_s"].get<double>(), 0.5e-3, 1.0 / 44100.0);
  std::printf("attack noise: %zu modes after the restart, %zu without\n", s["modes"].size(), t["modes"].size());
  EXPECT_GT(t["modes"].size(), s["modes"].size() + 2) << off.out;
  const CliRun bad = run("extract " + wav.string() + " --max-attack-skip-ms 500");
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("max-attack-skip-ms"), std::string::npos) << bad.err;
}

TEST_F(ExtractCli, StereoMixAndChannelChoice) {
  const auto mono = two_mode_impact(0.5);
  std::vector<float> stereo;
  for (float v : mono) {
    stereo.push_back(v);
    stereo.push_back(0.5f * v);
  }
  const fs::path wav = write("st.wav", stereo, 2);
  const CliRun left = run("extract " + wav.string() + " --json --channel 0");
  const CliRun mix = run("extract " + wav.string() + " --json");
  ASSERT_EQ(left.code, 0) << left.err;
  ASSERT_EQ(mix.code, 0) << mix.err;
  const double a_left = nlohmann::json::parse(left.out)["sounds"][0]["modes"][0]["amp"].get<double>();
  const double a_mix = nlohmann::json::parse(mix.out)["sounds"][0]["modes"][0]["amp"].get<double>();
  EXPECT_NEAR(a_left, 0.4, 0.004);
  EXPECT_NEAR(a_mix, 0.3, 0.003);  // (1 + 0.5) / 2 of the left channel
  const CliRun bad = run("extract " + wav.string() + " --channel 2");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("channel"), std::string::npos);
}

TEST_F(ExtractCli, RejectsSilence) { expect_rejected(write("zeros.wav", std::vector<float>(44100, 0.0f)), "silent"); }

TEST_F(ExtractCli, RejectsClipping) {
  std::vector<float> square(44100);
  for (std::size_t n = 0; n < square.size(); ++n) square[n] = (n / 50) % 2 ? 1.0f : -1.0f;
  expect_rejected(write("square.wav", square), "clipped");
}

TEST_F(ExtractCli, RejectsTooShort) {
  auto x = two_mode_impact(0.04);
  expect_rejected(write("short.wav", x), "too short");
}

TEST_F(ExtractCli, RejectsNonAudio) {
  const fs::path p = dir_ / "notes.wav";
  std::ofstream(p) << "this is a text file, not a RIFF header\n";
  expect_rejected(p, "not a readable audio file");
}

TEST_F(ExtractCli, RejectsMissingFile) { expect_rejected(dir_ / "nowhere.wav", "no such file"); }

TEST_F(ExtractCli, OneBadFileOutOfManyWritesNothing) {
  const fs::path good = write("good.wav", two_mode_impact(0.5));
  const fs::path bad = write("zeros.wav", std::vector<float>(44100, 0.0f));
  const fs::path csv = dir_ / "features.csv";
  const CliRun r = run("extract " + good.string() + " " + bad.string() + " -o " + csv.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("zeros.wav"), std::string::npos);
  EXPECT_FALSE(fs::exists(csv));
}

// The recordings are fitted side by side, but the CSV keeps the order they were given in and, of two
// bad files, the first given is the one named (as one after another would).
TEST_F(ExtractCli, ManyFilesKeepTheirOrderAndTheFirstBadIsNamed) {
  const fs::path b = write("b.wav", two_mode_impact(0.5)), a = write("a.wav", two_mode_impact(0.5));
  const fs::path c = write("c.wav", two_mode_impact(0.5));
  const fs::path csv = dir_ / "features.csv";
  const CliRun ok = run("extract " + b.string() + " " + a.string() + " " + c.string() + " -o " + csv.string());
  ASSERT_EQ(ok.code, 0) << ok.err;
  std::vector<std::string> sounds;
  std::istringstream rows(slurp(csv));
  std::string row;
  std::getline(rows, row);  // header
  while (std::getline(rows, row))
    if (sounds.empty() || sounds.back() != row.substr(0, row.find(','))) sounds.push_back(row.substr(0, row.find(',')));
  EXPECT_EQ(sounds, (std::vector<std::string>{"b", "a", "c"}));
  EXPECT_EQ(ok.out.substr(0, 2), "b:") << ok.out;

  const fs::path silent = write("silent.wav", std::vector<float>(44100, 0.0f));
  const CliRun bad = run("extract " + a.string() + " " + silent.string() + " " + (dir_ / "nowhere.wav").string() +
                         " -o " + (dir_ / "other.csv").string());
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("silent.wav: silent"), std::string::npos) << bad.err;
  EXPECT_EQ(bad.err.find("nowhere.wav"), std::string::npos) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "other.csv"));
}

}  // namespace

namespace {

// The first number after `key: [` in a YAML flow list, and how many numbers the list holds.
std::pair<double, std::size_t> first_and_count(const std::string& yaml, const std::string& key) {
  const std::size_t open = yaml.find(key + ": [");
  if (open == std::string::npos) return {0.0, 0};
  const std::size_t close = yaml.find(']', open);
  const std::string list = yaml.substr(open + key.size() + 3, close - open - key.size() - 3);
  return {std::stod(list), std::size_t(std::count(list.begin(), list.end(), ',') + 1)};
}

}  // namespace

// --object-out: the recording's modes as an eigenvalues object, which synth renders at the recording's
// frequencies (with the material's damping) and estimate takes as its object.
TEST_F(ExtractCli, ObjectOutRendersTheRecordingsFrequencies) {
  const fs::path wav = write("bowl.wav", two_mode_impact(1.0, 0.05));
  const fs::path object = dir_ / "object.yaml";
  const CliRun r = run("extract " + wav.string() + " --object-out " + object.string() + " --material ren2013/glass");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string yaml = slurp(object);
  EXPECT_NE(yaml.find("type: eigenvalues"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("material: ren2013/glass"), std::string::npos) << yaml;
  EXPECT_EQ(first_and_count(yaml, "gains"), std::make_pair(1.0, std::size_t(2))) << yaml;  // the loudest is 1

  const fs::path modes = dir_ / "rendered.csv", out = dir_ / "rendered.wav";
  const CliRun synth = run("synth " + object.string() + " -o " + out.string() + " --modes-out " + modes.string());
  ASSERT_EQ(synth.code, 0) << synth.err;
  // freq_hz of each rendered mode: the measured ones (the glass' damping moves them by ~0.003 Hz)
  std::vector<double> freqs;
  std::istringstream csv(slurp(modes));
  std::string line;
  std::getline(csv, line);
  while (std::getline(csv, line)) freqs.push_back(std::stod(line));
  ASSERT_EQ(freqs.size(), 2u);
  EXPECT_NEAR(freqs[0], 523.0, 0.01);
  EXPECT_NEAR(freqs[1], 1870.0, 0.02);

  // A stiffness of one's own choosing scales the eigenvalues: lambda0 = omega^2 / (E/rho).
  const fs::path scaled = dir_ / "scaled.yaml";
  ASSERT_EQ(run("extract " + wav.string() + " --object-out " + scaled.string() + " --specific-modulus 1e6").code, 0);
  const double omega = 2.0 * 3.14159265358979 * 523.0;
  EXPECT_NEAR(first_and_count(slurp(scaled), "lambda0").first, omega * omega / 1e6, 1e-4 * omega * omega / 1e6);
}

TEST_F(ExtractCli, ObjectOutRefusesTwoRecordingsAndUnknownMaterials) {
  const fs::path a = write("a.wav", two_mode_impact(1.0)), b = write("b.wav", two_mode_impact(1.0));
  const fs::path object = dir_ / "object.yaml";
  const CliRun two = run("extract " + a.string() + " " + b.string() + " --object-out " + object.string());
  EXPECT_EQ(two.code, 2) << two.err;
  EXPECT_NE(two.err.find("exactly one recording"), std::string::npos) << two.err;
  const CliRun unknown = run("extract " + a.string() + " --object-out " + object.string() + " --material ren2013/cheese");
  EXPECT_EQ(unknown.code, 2) << unknown.err;
  EXPECT_NE(unknown.err.find("cheese"), std::string::npos) << unknown.err;
  EXPECT_EQ(std::count(unknown.err.begin(), unknown.err.end(), '\n'), 1) << unknown.err;
  EXPECT_FALSE(fs::exists(object));
}
