// `modalstudy estimate -o MATERIAL.yaml` writes MATERIAL.residual.msr beside the material, a parameter
// set names both and `synth` renders it; a rejected recording leaves neither file.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_util.hpp"
#include "synthesis/residual_file.hpp"

using ms::test::run_cli;
using ms::test::TempDir;

TEST(EstimateCliResidual, WrittenBesideTheMaterialAndUsedBySynth) {
  TempDir dir;
  const std::string bar = MODALSTUDY_SOURCE_DIR "/stimuli/bar/ren-glass.yaml";
  ASSERT_EQ(run_cli("synth " + bar + " --set effects.transient.level_db=-15 --set effects.transient.duration_ms=10 -o " +
                        dir.file("glass.wav"),
                    dir)
                .exit_code,
            0);
  const auto r = run_cli("estimate " + dir.file("glass.wav") + " --object " + bar + " -o " + dir.file("glass.yaml"), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("residual file: " + dir.file("glass.residual.msr")), std::string::npos) << r.out;
  const ms::ResidualSpectrogram residual = ms::read_residual_file(dir.file("glass.residual.msr"));
  EXPECT_EQ(residual.sample_rate_hz, 44100.0);
  EXPECT_GE(residual.modes.size(), 3u);
  double energy = 0.0;
  for (float v : residual.power) energy += v;
  EXPECT_GT(energy, 0.0);  // the transient the modes cannot make
  dir.write("bigger.yaml", "sample_rate: 44100\nduration_s: 1.0\n"
                           "object: {type: bar, length_m: 0.375, thickness_m: 0.018, hit_position: 0.1}\n"
                           "material: {file: glass.yaml}\nresidual: {file: glass.residual.msr, gain_db: -3}\n");
  const auto s = run_cli("synth " + dir.file("bigger.yaml") + " -o " + dir.file("bigger.wav"), dir);
  EXPECT_EQ(s.exit_code, 0) << s.err;
  EXPECT_TRUE(std::filesystem::exists(dir.file("bigger.wav")));
}

TEST(EstimateCliResidual, ARejectedRecordingWritesNoResidual) {
  TempDir dir;
  dir.write("silent.wav", "");
  const auto r = run_cli("estimate " + dir.file("silent.wav") + " --object " MODALSTUDY_SOURCE_DIR
                         "/stimuli/bar/ren-wood.yaml -o " + dir.file("m.yaml"),
                         dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.yaml")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.residual.msr")));
}
