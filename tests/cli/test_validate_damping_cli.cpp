// modalstudy validate-damping: the JSON and the pictures of a small run, and bad input as one line.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "support/test_util.hpp"

namespace {

TEST(CliValidateDamping, JsonCarriesBothParametersPerEstimatorAndPlotsTwoPanels) {
  ms::test::TempDir dir;
  const std::string fig = (dir.path() / "fig.svg").string();
  const auto r = ms::test::run_cli("validate-damping --material sterling2019/steel --sounds 1,3 --resamples 3 "
                                   "--plot " + fig + " --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["sound_counts"], nlohmann::json::array({1, 3}));
  EXPECT_GT(j["truth"]["alpha1"].get<double>(), 0);
  ASSERT_EQ(j["estimators"].size(), 4u);
  for (const auto& e : j["estimators"]) {
    ASSERT_EQ(e["alpha1_median_rel_error"].size(), 2u) << e["name"];
    ASSERT_EQ(e["alpha2_median_rel_error"].size(), 2u) << e["name"];
    for (const auto& v : e["alpha2_median_rel_error"]) EXPECT_GE(v.get<double>(), 0.0);
  }
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "fig-alpha1.svg"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "fig-alpha2.svg"));
}

TEST(CliValidateDamping, BadInputIsOneLine) {
  ms::test::TempDir dir;
  for (const std::string args : {"validate-damping --material unobtainium", "validate-damping --material sterling2019/steel --sounds 0",
                                 "validate-damping --material sterling2019/steel --plot fig.jpg"}) {
    const auto r = ms::test::run_cli(args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(ms::test::count_lines(r.err), 1u) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "fig-alpha1.jpg"));
}

}  // namespace
