// Parameter sets with `residual: {file, gain_db, seed}`: the set's sound is its modes plus the
// residual transferred to them, the file and every value enter the recipe hash, the key survives
// write_yaml, and every mistake is one located line.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "residual_fixture.hpp"
#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/residual_transfer.hpp"
#include "synthesis/stimulus.hpp"

using namespace ms;

namespace {

constexpr double kFs = 44100.0;

ResidualSpectrogram burst_residual(double sample_rate_hz = kFs) {
  return test::noise_burst_residual({Mode{440.0, 6.0, 0.3, 0.0}, Mode{1500.0, 20.0, 0.1, 0.0}}, 0.05, 80.0, 8000, 2,
                                    sample_rate_hz);
}

const char* kSet = R"(sample_rate: 44100
duration_s: 0.5
modes:
  - {freq_hz: 440, decay_per_s: 6, amp: 0.3}
  - {freq_hz: 1500, decay_per_s: 20, amp: 0.1}
level: {normalize: none}
)";

std::string error_of(const test::TempDir& dir, const std::string& residual_line) {
  try {
    load_paramset(dir.write("set.yaml", std::string(kSet) + residual_line + "\n"));
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ParamSetResidual, TheSoundIsTheModesPlusTheTransferredResidual) {
  test::TempDir dir;
  write_residual_file(dir.file("wood.residual.msr"), burst_residual());
  const ParamSet plain = load_paramset(dir.write("plain.yaml", kSet));
  const ParamSet with = load_paramset(
      dir.write("with.yaml", std::string(kSet) + "residual: {file: wood.residual.msr, gain_db: -6, seed: 7}\n"));
  ASSERT_TRUE(with.residual.spectrogram);
  EXPECT_EQ(with.residual.gain_db, -6.0);
  EXPECT_EQ(with.residual.seed, 7u);
  const std::vector<float> a = render_stimulus(plain).audio.samples, b = render_stimulus(with).audio.samples;
  ASSERT_EQ(a.size(), b.size());
  GriffinLimOptions options;
  options.seed = 7;
  const GriffinLimResult residual =
      render_transferred_residual(*with.residual.spectrogram, heard_modes(with.model.modes, with.excitation), kFs,
                                  a.size(), options);
  const double gain = std::pow(10.0, -6.0 / 20.0);
  double worst = 0.0, energy = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(double(b[i]) - double(a[i]) - gain * residual.samples[i]));
    energy += double(b[i] - a[i]) * double(b[i] - a[i]);
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(energy, 1e-3);  // the residual is there
  // The same recipe renders the same samples.
  EXPECT_EQ(render_stimulus(load_paramset(dir.file("with.yaml"))).audio.samples, b);
}

TEST(ParamSetResidual, FileGainAndSeedEnterTheHash) {
  test::TempDir dir;
  write_residual_file(dir.file("r.msr"), burst_residual());
  auto hash = [&](const std::string& line) {
    return load_paramset(dir.write("set.yaml", std::string(kSet) + line + "\n")).recipe_hash;
  };
  const std::string none = hash(""), base = hash("residual: {file: r.msr}");
  EXPECT_NE(base, none);
  EXPECT_NE(hash("residual: {file: r.msr, gain_db: 3}"), base);
  EXPECT_NE(hash("residual: {file: r.msr, seed: 1}"), base);
  ResidualSpectrogram other = burst_residual();
  other.power[100] *= 2.0f;
  write_residual_file(dir.file("r.msr"), other);
  EXPECT_NE(hash("residual: {file: r.msr}"), base);
}

TEST(ParamSetResidual, TheKeySurvivesWriteYaml) {
  test::TempDir dir;
  write_residual_file(dir.file("r.msr"), burst_residual());
  const ParamSetRecipe recipe =
      read_recipe(std::string(kSet) + "residual: {file: r.msr, gain_db: -2.5, seed: 3}\n", "set.yaml", dir.path().string());
  const std::string yaml = write_yaml(recipe);
  EXPECT_NE(yaml.find("residual: {file: r.msr, gain_db: -2.5, seed: 3}"), std::string::npos) << yaml;
  const ParamSetRecipe back = read_recipe(yaml, "set.yaml", dir.path().string());
  ASSERT_TRUE(back.residual);
  EXPECT_EQ(back.residual->file, "r.msr");
  EXPECT_EQ(back.residual->gain_db, -2.5);
  EXPECT_EQ(back.residual->seed, 3u);
  EXPECT_EQ(write_yaml(back), yaml);
}

TEST(ParamSetResidual, MistakesAreOneLocatedLine) {
  test::TempDir dir;
  write_residual_file(dir.file("r.msr"), burst_residual());
  write_residual_file(dir.file("r48.msr"), burst_residual(48000.0));
  EXPECT_NE(error_of(dir, "residual: {gain_db: 3}").find("set.yaml:7:11: residual: expected {file:"), std::string::npos)
      << error_of(dir, "residual: {gain_db: 3}");
  EXPECT_NE(error_of(dir, "residual: {file: r.msr, gain: 3}").find("unknown key 'residual.gain' (did you mean 'gain_db'?)"),
            std::string::npos);
  EXPECT_NE(error_of(dir, "residual: {file: r.msr, gain_db: 90}").find("residual.gain_db: must lie in [-120, 40] dB"),
            std::string::npos);
  EXPECT_NE(error_of(dir, "residual: {file: missing.msr}").find("set.yaml:7:18: residual.file: cannot use"),
            std::string::npos);
  EXPECT_NE(error_of(dir, "residual: {file: ../../etc/passwd}").find("set.yaml:7:18: residual.file:"), std::string::npos);
  EXPECT_NE(error_of(dir, "residual: {file: r48.msr}").find("was made at 48000 Hz, the set renders at 44100 Hz"),
            std::string::npos);
  // A broken residual file is named at its own line.
  dir.write("bad.msr", "format: modalstudy-residual 1\nsample_rate_hz: fast\n...\n");
  EXPECT_NE(error_of(dir, "residual: {file: bad.msr}").find("bad.msr:2:17: sample_rate_hz"), std::string::npos)
      << error_of(dir, "residual: {file: bad.msr}");
}
