// modalstudy plot lines: perceived difference vs number of modes from tidy data, one line per method.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_util.hpp"

using namespace ms;

TEST(PlotLinesCli, DrawsMeansPerSeriesAndNamesBadColumns) {
  test::TempDir dir;
  const std::string data = std::string(MODALSTUDY_TEST_DATA) + "/plots/difference_vs_modes.csv";
  for (const char* file : {"lines.png", "lines.svg"}) {
    const auto r = test::run_cli("plot lines " + data + " --x modes --y difference --series method --log-x -o " +
                                     dir.file(file), dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_GT(std::filesystem::file_size(dir.file(file)), 2000u);
  }
  const auto bad = test::run_cli("plot lines " + data + " --x modes --y diference -o " + dir.file("bad.png"), dir);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("diference"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("bad.png")));
}
