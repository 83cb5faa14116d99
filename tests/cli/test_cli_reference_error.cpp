// modalstudy stats reference-error end to end: one analysis per attribute (--by), the JSON's mean
// errors and F as the library computes them, and bad input as one located line with exit 2.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/test_util.hpp"

using namespace ms;

namespace {

// Two attributes; per attribute three listeners rate two sounds in rec, a and b.
std::string ratings() {
  std::string csv = "participant,block,attribute,dataset,shape,material,value\n";
  const char* rows[] = {"p1,rec,disc,wood,3", "p1,rec,rod,metal,6", "p1,a,disc,wood,4", "p1,a,rod,metal,5",
                        "p1,b,disc,wood,1",   "p1,b,rod,metal,7",   "p2,rec,disc,wood,4", "p2,rec,rod,metal,4",
                        "p2,a,disc,wood,4",   "p2,a,rod,metal,6",   "p2,b,disc,wood,7",   "p2,b,rod,metal,1",
                        "p3,rec,disc,wood,2", "p3,rec,rod,metal,5", "p3,a,disc,wood,2",   "p3,a,rod,metal,5",
                        "p3,b,disc,wood,4",   "p3,b,rod,metal,6"};
  for (const char* attribute : {"duration", "pitch"})
    for (const char* r : rows) {
      std::string row = r;
      const std::size_t comma = row.find(',');
      csv += row.substr(0, comma) + ",ratings," + attribute + row.substr(comma) + "\n";
    }
  csv += "p1,training,duration,a,disc,wood,7\n";  // a training row, left out by --where
  return csv;
}

}  // namespace

TEST(CliStatsReferenceError, OneAnalysisPerAttribute) {
  test::TempDir dir;
  const std::string csv = dir.write("rating.csv", ratings());
  const auto r = test::run_cli("stats reference-error " + csv + " --reference rec --match shape,material --by attribute "
                               "--where block=ratings --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["analyses"].size(), 2u);
  for (const auto& a : j["analyses"]) {
    EXPECT_EQ(a["n_subjects"], 3);
    // a: 1, 1, 0 -> 2/3; b: 1.5, 3, 1.5 -> 2 (the hand computation of test_reference_error.cpp)
    EXPECT_NEAR(a["mean_error"]["a"].get<double>(), 2.0 / 3.0, 1e-12);
    EXPECT_NEAR(a["mean_error"]["b"].get<double>(), 2.0, 1e-12);
    EXPECT_EQ(a["df1"], 1.0);
    EXPECT_EQ(a["df2"], 2.0);
    EXPECT_GT(a["F"].get<double>(), 0.0);
    ASSERT_EQ(a["posthoc"]["pairs"].size(), 1u);
    EXPECT_EQ(a["posthoc"]["adjust"], "holm");
    EXPECT_NEAR(a["posthoc"]["pairs"][0]["mean_diff"].get<double>(), 2.0 / 3.0 - 2.0, 1e-12);
  }
  EXPECT_EQ(j["analyses"][0]["by"], "duration");
  // Without --where the training row joins p1's a ratings of the disc (mean of 4 and 7): a differs.
  const auto all = test::run_cli("stats reference-error " + csv + " --reference rec --match shape,material --by attribute --json", dir);
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_GT(nlohmann::json::parse(all.out)["analyses"][0]["mean_error"]["a"].get<double>(), 2.0 / 3.0 + 0.1);
}

TEST(CliStatsReferenceError, BadInputIsOneLocatedLine) {
  test::TempDir dir;
  const std::string csv = dir.write("rating.csv", ratings());
  for (const auto& [args, expect] : std::vector<std::pair<std::string, std::string>>{
           {" --reference real --match shape,material", "no row of the reference dataset 'real'"},
           {" --reference rec --match size", "size"},
           {" --reference rec --match shape,material --by mood", "mood"},
           {" --reference rec --match shape --dv participant", "rating.csv:2:"}}) {
    const auto r = test::run_cli("stats reference-error " + csv + args, dir);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(expect), std::string::npos) << args << ": " << r.err;
  }
}
