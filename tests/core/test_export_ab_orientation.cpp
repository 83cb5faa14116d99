// A/B answers turned to the protocol's written pair: the schedule randomises which stimulus of a pair
// is played as A, so a bipolar score (B compared with A) averaged in played order tends to 0 whatever
// the listeners heard. The export names the written pair, whether the trial was swapped, and the
// answer in the written order, and `stats ab --score response_oriented` summarises that.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"
#include "studyapp/core/autopilot.hpp"
#include "core_fixtures.hpp"
#include "support/test_util.hpp"

using namespace ms;

TEST(ExportAbOrientation, BipolarScoresAreTurnedToTheWrittenPair) {
  test::TempDir dir;
  const AutopilotOptions o = ms::testing::shipped_study("ab_synthesis_methods.yaml", dir);
  ASSERT_TRUE(ms::testing::run_participants_and_export(o, 3, "L", 40, dir.file("out")));
  const TidyCsv t = TidyCsv::read(dir.file("out/ab.csv"));
  ASSERT_EQ(t.rows(), 30u);  // 3 listeners x 10 pairs
  std::size_t swapped = 0;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const auto at = [&](const char* c) { return t.cell(r, t.column(c)); };
    // The written pair is [sinusoidal, filter-based]; the played order is either way round.
    EXPECT_EQ(at("pair_first").substr(0, 4), "sin-") << r;
    EXPECT_EQ(at("pair_second").substr(0, 4), "bpf-") << r;
    const bool is_swapped = at("swapped") == "1";
    EXPECT_EQ(is_swapped, at("stimulus_a") == at("pair_second")) << r;
    EXPECT_EQ(is_swapped ? at("stimulus_b") : at("stimulus_a"), at("pair_first")) << r;
    const double score = t.number(r, t.column("response")), oriented = t.number(r, t.column("response_oriented"));
    EXPECT_EQ(oriented, is_swapped ? -score : score) << r;
    swapped += is_swapped;
  }
  EXPECT_GT(swapped, 0u);  // the schedule does swap
  EXPECT_LT(swapped, t.rows());
  const auto r = test::run_cli("stats ab " + dir.file("out/ab.csv") +
                                   " --task preference --score response_oriented --by block --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["groups"].size(), 1u);
  EXPECT_EQ(j["groups"][0]["n"], 30);
  EXPECT_TRUE(j["groups"][0].contains("score"));
}

// Skandalou & Ireland's Fig. 5.2 and Table 5.3 from the shipped protocol's export, one call each: the
// stimuli's factors name object, material and location (the pair shares them; the method differs, so
// its cell is empty), and each group's mean is the mean of its oriented answers.
TEST(ExportAbOrientation, Figure52AndTable53AreOneCallEach) {
  test::TempDir dir;
  const AutopilotOptions o = ms::testing::shipped_study("ab_synthesis_methods.yaml", dir);
  ASSERT_TRUE(ms::testing::run_participants_and_export(o, 3, "L", 40, dir.file("out")));
  const TidyCsv t = TidyCsv::read(dir.file("out/ab.csv"));
  std::map<std::string, std::vector<double>> by_location;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const auto at = [&](const char* c) { return t.cell(r, t.column(c)); };
    EXPECT_EQ(at("pair_first"), "sin-" + at("object") + "-" + at("location")) << r;
    EXPECT_EQ(at("method"), "") << r;  // sinusoidal against filter-based: no shared level
    by_location[at("object") + "/" + at("location")].push_back(t.number(r, t.column("response_oriented")));
  }
  ASSERT_EQ(by_location.size(), 10u);
  const std::string csv = dir.file("out/ab.csv");
  const auto fig = test::run_cli("stats ab " + csv + " --task preference --score response_oriented --by object,location "
                                 "--where block=methods --options sinusoidal,filter-based --json", dir);
  ASSERT_EQ(fig.exit_code, 0) << fig.err;
  const auto j = nlohmann::json::parse(fig.out);
  ASSERT_EQ(j["groups"].size(), 10u);
  for (const auto& g : j["groups"]) {
    const auto& v = by_location.at(g["group"].get<std::string>());
    double mean = 0;
    for (double x : v) mean += x / double(v.size());
    EXPECT_EQ(g["score"]["n"], 3);
    EXPECT_NEAR(g["score"]["mean"].get<double>(), mean, 1e-12) << g["group"];
    EXPECT_TRUE(g["score"].contains("sd"));
  }
  const auto table = test::run_cli("stats ab " + csv + " --task preference --score response_oriented --by material "
                                   "--subject participant --where block=methods --options sinusoidal,filter-based", dir);
  ASSERT_EQ(table.exit_code, 0) << table.err;
  for (const char* material : {"plastic", "wood", "ceramic", "glass", "metal"})
    EXPECT_NE(table.out.find(std::string("\n") + material + " "), std::string::npos) << material << "\n" << table.out;
  EXPECT_NE(table.out.find("+ favours filter-based, - favours sinusoidal; 5 group(s)"), std::string::npos) << table.out;
}
