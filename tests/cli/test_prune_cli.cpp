// modalstudy prune: options, JSON shape, --keep output, and every kind of bad input (exit code 2,
// one line naming the file, no output file left behind). Expected numbers:
// tests/data/masking_pruning/hand_values.py.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int code = -1;
  std::string out, err;
};

class PruneCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("modalstudy_prune_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }

  static std::string slurp(const std::string& file) {
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  CliRun run(const std::string& args) const {
    const std::string out = path("stdout.txt"), err = path("stderr.txt");
    const std::string cmd = std::string("cd '") + dir_.string() + "' && '" + MODALSTUDY_BIN + "' prune " +
                            args + " >'" + out + "' 2>'" + err + "'";
    const int status = std::system(cmd.c_str());
    CliRun r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  // Bad input: exit code 2, exactly one line on stderr containing `where` and `what`, nothing on
  // stdout and no output file.
  void expect_rejected(const std::string& args, const std::string& where, const std::string& what) {
    const CliRun r = run(args + " -o out.csv");
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(where), std::string::npos) << "want '" << where << "' in: " << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << "want '" << what << "' in: " << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(path("out.csv"))) << args;
    for (const auto& entry : fs::directory_iterator(dir_))  // no temporary left either
      EXPECT_EQ(entry.path().filename().string().find(".out.csv.tmp"), std::string::npos);
  }

  fs::path dir_;
};

// The three-mode model of the analysis tests: naive 0,1,2; energy 2,1,0; loudness 1,2,0.
const char* kThree =
    "# three modes\n"
    "freq_hz,decay_per_s,amp\n"
    "1100,10,1\n"
    "1000,1,0.5\n"
    "60,0.5,0.4\n";

TEST_F(PruneCli, JsonShape) {
  write("m.csv", kThree);
  const CliRun r = run("m.csv --method masking --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["kept"], nlohmann::json({2, 1, 0}));
  EXPECT_EQ(j["dropped"], nlohmann::json::array());
  ASSERT_EQ(j["levels_db"].size(), 3u);
  EXPECT_NEAR(j["levels_db"][0].get<double>(), 61.739251972992, 1e-9);  // 70 + 10 log10(0.1/0.67)
  EXPECT_NEAR(j["levels_db"][2].get<double>(), 66.790751756191, 1e-9);  // 70 + 10 log10(0.32/0.67)
  EXPECT_NEAR(j["masking_threshold_db"][0].get<double>(), 44.256321403723, 1e-9);
  EXPECT_NEAR(j["threshold_in_quiet_db"][2].get<double>(), 34.548575988102, 1e-9);
  EXPECT_EQ(j["method"], "masking");
  EXPECT_EQ(j["order"], "energy");
  EXPECT_EQ(j["combine"], "max");
  EXPECT_EQ(j["threshold_db"], 16.0);
  EXPECT_EQ(j["playback_db"], 70.0);
  EXPECT_EQ(j["modes"], 3);
  EXPECT_FALSE(j.contains("output"));
}

TEST_F(PruneCli, EachOrderAndEachBaseline) {
  write("m.csv", kThree);
  auto kept = [&](const std::string& args) {
    const CliRun r = run("m.csv " + args + " --json");
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out)["kept"];
  };
  EXPECT_EQ(kept("--method masking --order naive"), nlohmann::json({0, 1, 2}));
  EXPECT_EQ(kept("--method masking --order energy"), nlohmann::json({2, 1, 0}));
  EXPECT_EQ(kept("--method masking --order loudness"), nlohmann::json({1, 2, 0}));
  EXPECT_EQ(kept("--method naive"), nlohmann::json({0, 1, 2}));
  EXPECT_EQ(kept("--method energy"), nlohmann::json({2, 1, 0}));
  EXPECT_EQ(kept("--method loudness"), nlohmann::json({1, 2, 0}));
}

TEST_F(PruneCli, ThresholdPlaybackAndCombineChangeTheVerdict) {
  // Case A of the analysis tests: mode 1 is 5.54 dB above mode 0's masking at a_v 16, 0.46 dB
  // under it at a_v 10.
  write("a.csv", "freq_hz,decay_per_s,amp\n1000,1,1\n1200,1,0.1\n");
  auto json = [&](const std::string& args) {
    const CliRun r = run("a.csv --method masking --json " + args);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  EXPECT_EQ(json("")["kept"], nlohmann::json({0, 1}));
  const auto j = json("--threshold-db 10 --playback-db 80 --combine sum");
  EXPECT_EQ(j["kept"], nlohmann::json({0}));
  EXPECT_EQ(j["dropped"], nlohmann::json({1}));
  EXPECT_EQ(j["threshold_db"], 10.0);
  EXPECT_EQ(j["playback_db"], 80.0);
  EXPECT_EQ(j["combine"], "sum");
  EXPECT_NEAR(j["levels_db"][0].get<double>(), 79.956786262174, 1e-9);
  // At 80 dB mode 0's upper slope is 22 - 79.957/5 = 6.0086, so it masks more: 79.957 - 10 - 6.0086
  // * 1.191321 = 62.799 dB, above L1 = 59.957.
  EXPECT_NEAR(j["masking_threshold_db"][1].get<double>(), 62.798566186569, 1e-9);  // hand_values.py
}

TEST_F(PruneCli, SilentModeIsNullInJson) {
  write("z.csv", "freq_hz,decay_per_s,amp\n1000,1,0\n2000,1,1\n");
  const CliRun r = run("z.csv --method masking --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["levels_db"][0].is_null());
  EXPECT_EQ(j["levels_db"][1], 70.0);
  EXPECT_TRUE(j["masking_threshold_db"][1].is_null());  // the silent mode masks nothing
  EXPECT_EQ(j["kept"], nlohmann::json({1}));
  EXPECT_EQ(j["dropped"], nlohmann::json({0}));
  EXPECT_EQ(r.out.find("nan"), std::string::npos);
}

TEST_F(PruneCli, KeepWritesTheFirstKSurvivorsInOrder) {
  write("m.csv", kThree);
  const CliRun r = run("m.csv --method masking --order energy --keep 2 -o out.csv --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(path("out.csv")),
            "freq_hz,decay_per_s,amp,phase_rad\r\n"
            "60,0.5,0.40000000000000002,0\r\n"
            "1000,1,0.5,0\r\n");
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["written"], 2);
  EXPECT_EQ(j["kept"], nlohmann::json({2, 1, 0}));  // kept lists every survivor

  // Without --keep, -o writes every survivor; --keep beyond the survivors writes what there is.
  ASSERT_EQ(run("m.csv --method naive -o all.csv").code, 0);
  EXPECT_EQ(slurp(path("all.csv")),
            "freq_hz,decay_per_s,amp,phase_rad\r\n1100,10,1,0\r\n1000,1,0.5,0\r\n60,0.5,0.40000000000000002,0\r\n");
  const CliRun more = run("m.csv --method masking --keep 50 -o more.csv");
  ASSERT_EQ(more.code, 0) << more.err;
  EXPECT_NE(more.out.find("wrote 3 modes"), std::string::npos) << more.out;
}

TEST_F(PruneCli, TextReportListsKeptModesInOrder) {
  write("m.csv", kThree);
  const CliRun r = run("m.csv --method masking --order loudness");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("3 of 3 modes kept"), std::string::npos) << r.out;
  const auto first = r.out.find("    1     1 ");
  const auto second = r.out.find("    2     2 ");
  const auto third = r.out.find("    3     0 ");
  EXPECT_TRUE(first != std::string::npos && first < second && second < third) << r.out;
}

TEST_F(PruneCli, HelpDocumentsTheBaselines) {
  const CliRun r = run("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("apply no masking"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("null"), std::string::npos);
}

TEST_F(PruneCli, BadInputExitsTwoWithOneLineAndNoOutput) {
  write("m.csv", kThree);
  expect_rejected("missing.csv --method masking", "missing.csv", "no such file");
  write("cols.csv", "freq_hz,amp\n100,1\n");
  expect_rejected("cols.csv --method masking", "cols.csv:1", "missing column 'decay_per_s'");
  write("nan.csv", "freq_hz,decay_per_s,amp\n100,1,1\n200,nan,1\n");
  expect_rejected("nan.csv --method masking", "nan.csv:3:5", "decay_per_s");
  write("neg.csv", "freq_hz,decay_per_s,amp\n100,1,1\n200,-2,1\n");
  expect_rejected("neg.csv --method masking", "neg.csv:3:5", "must not be negative");
  write("zero.csv", "# comment\nfreq_hz,decay_per_s,amp\n100,1,1\n\n200,0,1\n");
  expect_rejected("zero.csv --method masking", "zero.csv:5:", "infinite power");
  expect_rejected("m.csv --method masking --threshold-db 60.5", "m.csv", "--threshold-db 60.5 is outside [-20, 60]");
  expect_rejected("m.csv --method masking --threshold-db -21", "m.csv", "--threshold-db");
  expect_rejected("m.csv --method masking --playback-db 131", "m.csv", "--playback-db 131 is outside [0, 130]");
  expect_rejected("m.csv --method masking --playback-db -1", "m.csv", "--playback-db");
  expect_rejected("m.csv --method masking --playback-db nan", "m.csv", "--playback-db");
  expect_rejected("m.csv --method masking --keep 0", "m.csv", "--keep");
  expect_rejected("m.csv --method masking --keep -3", "m.csv", "--keep");
  expect_rejected("m.csv --method masking --keep 2.5", "m.csv", "--keep");
  expect_rejected("m.csv --method loud", "m.csv", "--method");
  expect_rejected("m.csv", "m.csv", "--method is required");
  expect_rejected("m.csv --method masking --combine avg", "m.csv", "--combine");
  expect_rejected("m.csv --method masking --order gain", "m.csv", "--order");
  expect_rejected("m.csv --method energy --order loudness", "m.csv", "--order applies to --method masking");
  // --keep without -o (checked without the helper's -o).
  const CliRun r = run("m.csv --method masking --keep 2");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--keep needs -o"), std::string::npos) << r.err;
}

TEST_F(PruneCli, FailedRunLeavesAnExistingOutputUntouched) {
  write("zero.csv", "freq_hz,decay_per_s,amp\n100,0,1\n");
  write("out.csv", "previous\n");
  EXPECT_EQ(run("zero.csv --method masking -o out.csv").code, 2);
  EXPECT_EQ(slurp(path("out.csv")), "previous\n");
}

}  // namespace
