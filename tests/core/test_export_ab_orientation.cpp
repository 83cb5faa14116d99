// A/B answers turned to the protocol's written pair: the schedule randomises which stimulus of a pair
// is played as A, so a bipolar score (B compared with A) averaged in played order tends to 0 whatever
// the listeners heard. The export names the written pair, whether the trial was swapped, and the
// answer in the written order, and `stats ab --score response_oriented` summarises that.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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
