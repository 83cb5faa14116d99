// modalstudy protocol check / schedule: every problem printed, exit codes, JSON shape.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"

using ms::test::run_cli;
using ms::test::TempDir;

namespace {
// A real (short) recording: protocol check reads every recording as a session start does.
void write_recording(const ms::test::TempDir& dir, const std::string& name) {
  ms::write_wav(dir.file(name), ms::Audio{44100, 1, std::vector<float>(441, 0.1f)}, ms::SampleFormat::float32);
}

const std::string kDemo = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/demo.yaml";
}

TEST(ProtocolCli, DemoChecksClean) {
  TempDir dir;
  const auto r = run_cli("protocol check " + kDemo + " --json", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["problems"].empty());
  EXPECT_EQ(j["blocks"], 14);
}

// A limits block that ascends is refused in one located line, exit 2; a good one schedules one trial
// per series (the series itself descends at run time).
TEST(ProtocolCli, LimitsBlockCheckedAndScheduled) {
  TempDir dir;
  const std::string set = std::string(MODALSTUDY_SOURCE_DIR) + "/stimuli/replications/vandendoel2002/vase.yaml";
  const std::string head = "study: t\nsample_rate: 22050\nallow_outside: true\nstimuli:\n  v: {paramset: " + set +
                           ", prune: {method: masking, threshold_db: 20}}\nblocks:\n";
  const std::string bad = dir.write("bad.yaml", head + "  - {type: limits, id: l, stimulus: v, parameter: prune.threshold_db, "
                                                       "start: 20, step: 1}\n");
  const auto r = run_cli("protocol check " + bad, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(ms::test::count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find(bad + ":7:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("negative step"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  const std::string good = dir.write("good.yaml", head + "  - {type: limits, id: l, stimulus: v, parameter: prune.threshold_db, "
                                                         "start: 20, step: -1, floor: 0, repeats: 3}\n");
  const auto ok = run_cli("protocol check " + good, dir);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  const auto s = run_cli("protocol schedule " + good + " --participant P1 --json", dir);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto j = nlohmann::json::parse(s.out);
  ASSERT_TRUE(j.contains("trials")) << s.out;
  EXPECT_EQ(j["trials"].size(), 3u);  // three series
  for (const auto& t : j["trials"]) EXPECT_EQ(t["type"], "limits") << t.dump();
}

TEST(ProtocolCli, EveryProblemOnItsOwnLineAndExit2) {
  TempDir dir;
  write_recording(dir, "a.wav");
  const std::string p = dir.write("p.yaml",
                                  "study: t\nstimuli:\n  a: {file: a.wav}\nblocks:\n"
                                  "  - {type: ab, id: x, pairs: [[a, c]]}\n  - {type: abb}\n"
                                  "  - {type: identify, id: x, stimuli: [a], labels: [l]}\n");
  const auto r = run_cli("protocol check " + p, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(ms::test::count_lines(r.err), 3u) << r.err;
  EXPECT_NE(r.err.find(p + ":5:35: block 'x': unknown stimulus 'c'"), std::string::npos) << r.err;
  const auto rj = run_cli("protocol check " + p + " --json", dir);
  EXPECT_EQ(rj.exit_code, 2);
  EXPECT_EQ(nlohmann::json::parse(rj.out)["problems"].size(), 3u);
}

TEST(ProtocolCli, ScheduleIsReproducible) {
  TempDir dir;
  const auto a = run_cli("protocol schedule " + kDemo + " --participant P01 --json", dir);
  const auto b = run_cli("protocol schedule " + kDemo + " --participant P01 --json", dir);
  const auto c = run_cli("protocol schedule " + kDemo + " --participant P02", dir);
  EXPECT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(c.exit_code, 0) << c.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_FALSE(nlohmann::json::parse(a.out)["trials"].empty());
  EXPECT_NE(c.out.find("mushra"), std::string::npos);
}
