// `modalstudy stats adjust`: the hand-tuning analysis in one call on an adjust.csv. The JSON carries the
// numbers R gives (tests/data/adjust/golden.csv, checked in full by AdjustSummary.*); the table prints
// every object, its section pooled, and the error against the truth; a mistake is one located line on
// stderr, exit 2, nothing on stdout.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_util.hpp"

namespace {

const std::string kData = std::string(MODALSTUDY_SOURCE_DIR) + "/tests/data/adjust/";

TEST(CliStatsAdjust, JsonCarriesRsNumbers) {
  const ms::test::TempDir dir;
  const auto r = ms::test::run_cli("stats adjust '" + kData + "adjust.csv' --object object --group section --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["objects"].size(), 6u);
  ASSERT_EQ(j["groups"].size(), 2u);
  const auto& porcelain = j["objects"][0];
  EXPECT_EQ(porcelain["group"], "three");
  EXPECT_EQ(porcelain["object"], "porcelain");
  // golden.csv: three, porcelain, time_s median 148.63105000000002, outlier 315.72490000000005; plays q3 51.75
  EXPECT_NEAR(porcelain["time_s"]["median"].get<double>(), 148.63105000000002, 1e-9);
  EXPECT_EQ(porcelain["time_s"]["outliers"].size(), 1u);
  EXPECT_NEAR(porcelain["time_s"]["outliers"][0].get<double>(), 315.72490000000005, 1e-9);
  EXPECT_NEAR(porcelain["plays"]["q3"].get<double>(), 51.75, 1e-12);
  const auto& alpha1 = porcelain["parameters"][0];
  EXPECT_EQ(alpha1["key"], "damping.alpha1");
  EXPECT_NEAR(alpha1["truth"].get<double>(), 3.9, 1e-12);
  EXPECT_NEAR(alpha1["chosen"]["q1"].get<double>(), 3.2813350000000003, 1e-12);
  EXPECT_TRUE(alpha1["log10_ratio"].is_object());
  // The cymbal's truth is NA: no error statistics.
  for (const auto& o : j["objects"])
    if (o["object"] == "cymbal")
      for (const auto& p : o["parameters"]) EXPECT_TRUE(p["log10_ratio"].is_null()) << p["key"];
}

TEST(CliStatsAdjust, TablePrintsObjectsSectionsAndErrors) {
  const ms::test::TempDir dir;
  const auto r = ms::test::run_cli("stats adjust '" + kData + "adjust.csv' --object object --group section", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("three porcelain "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("two   (all objects)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(1 not positive, left out)"), std::string::npos) << r.out;  // the wood alpha1 at 0
}

TEST(CliStatsAdjust, MistakesAreOneLineExitTwoAndNoOutput) {
  const ms::test::TempDir dir;
  const std::string bad = dir.write("bad.csv", "participant,session,block,trial,stimulus,key,value,plays,rt_ms\n"
                                               "p1,1,b,0,tune,damping.alpha1,30,12,90000\n"
                                               "p1,1,b,0,tune,damping.alpha2,2e-8,13,90000\n");
  auto r = ms::test::run_cli("stats adjust '" + bad + "'", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(r.err, "modalstudy: " + bad + ":3:35: column 'plays': differs from line 2 of the same answer (one answer's rows share it)\n");
  r = ms::test::run_cli("stats adjust '" + kData + "adjust.csv' --truth true_value", dir);  // given, so required
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("missing column 'true_value'"), std::string::npos) << r.err;
  EXPECT_EQ(ms::test::count_lines(r.err), 1u);
  r = ms::test::run_cli("stats adjust '" + dir.file("none.csv") + "'", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(ms::test::count_lines(r.err), 1u);
}

}  // namespace
