// `modalstudy stats ab --task preference --score`: per group n, mean, sd and R's one-sample t.test
// against 0 (tests/data/ab_summary/score_golden.csv, make_score_golden.R), on the rows or on each
// participant's mean (--subject); groups whose scores are all equal or single are summarised without a
// test instead of stopping the command; the side each group favours (Table 5.3 of Skandalou & Ireland
// 2017) named by --options; mistakes one located line.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "support/test_util.hpp"
#include "synthesis/tidy_csv.hpp"

namespace {

const std::string kData = std::string(MODALSTUDY_SOURCE_DIR) + "/tests/data/ab_summary/";

void expect_golden(const nlohmann::json& groups, const std::string& averaged) {
  const ms::TidyCsv g = ms::TidyCsv::read(kData + "score_golden.csv");
  std::size_t compared = 0;
  for (std::size_t r = 0; r < g.rows(); ++r) {
    if (g.cell(r, g.column("averaged")) != averaged) continue;
    const std::string material = g.cell(r, g.column("material"));
    const nlohmann::json* group = nullptr;
    for (const auto& x : groups)
      if (x["group"] == material) group = &x;
    ASSERT_NE(group, nullptr) << material;
    const auto& sc = (*group)["score"];
    EXPECT_EQ(sc["n"].get<std::size_t>(), std::size_t(g.number(r, g.column("n")))) << material;
    for (const char* key : {"mean", "sd", "t", "df", "p", "ci_low", "ci_high"}) {
      const std::string want = g.cell(r, g.column(key));
      if (want == "NA") {
        EXPECT_TRUE(sc[key].is_null()) << averaged << " " << material << " " << key << " = " << sc[key];
      } else {
        ASSERT_FALSE(sc[key].is_null()) << averaged << " " << material << " " << key;
        const double w = std::stod(want), got = sc[key].get<double>();
        EXPECT_NEAR(got, w, 1e-12 * std::max(1.0, std::abs(w))) << averaged << " " << material << " " << key;
      }
    }
    ++compared;
  }
  EXPECT_EQ(compared, 5u);
}

TEST(CliStatsAbScore, RowsAndSubjectMeansMatchR) {
  const ms::test::TempDir dir;
  const std::string base = "stats ab '" + kData + "scores.csv' --task preference --score response_oriented --by material";
  const auto rows = ms::test::run_cli(base + " --json", dir);
  ASSERT_EQ(rows.exit_code, 0) << rows.err;
  const auto j = nlohmann::json::parse(rows.out);
  expect_golden(j["groups"], "rows");
  // Participants answer twice per material: said once, not silently pooled as independent.
  EXPECT_NE(rows.err.find("a participant has more than one score in a group"), std::string::npos) << rows.err;
  EXPECT_NE(rows.err.find("no t-test where a group has one score or all its scores are equal"), std::string::npos);
  const auto subjects = ms::test::run_cli(base + " --subject participant --json", dir);
  ASSERT_EQ(subjects.exit_code, 0) << subjects.err;
  expect_golden(nlohmann::json::parse(subjects.out)["groups"], "participant");
  EXPECT_NE(subjects.err.find("scores averaged per subject"), std::string::npos) << subjects.err;
}

TEST(CliStatsAbScore, EachGroupSaysWhichSideItFavours) {
  const ms::test::TempDir dir;
  const std::string base = "stats ab '" + kData + "scores.csv' --task preference --score response_oriented --by material";
  const auto j = nlohmann::json::parse(ms::test::run_cli(base + " --json", dir).out);
  std::map<std::string, std::string> favours;
  for (const auto& g : j["groups"]) favours[g["group"]] = g["score"]["favours"];
  // plastic: interval [-0.10, 2.77] holds 0; wood: [-2.60, -0.40] below it; ceramic all 0; glass all -3
  // (every listener the first); metal one score.
  EXPECT_EQ(favours, (std::map<std::string, std::string>{
                         {"plastic", "neither"}, {"wood", "first"}, {"ceramic", "neither"}, {"glass", "first"},
                         {"metal", "neither"}}));
  const auto named = ms::test::run_cli(base + " --options sinusoidal,filter-based", dir);
  ASSERT_EQ(named.exit_code, 0) << named.err;
  EXPECT_NE(named.out.find("+ favours filter-based, - favours sinusoidal; 5 group(s)"), std::string::npos) << named.out;
  for (const char* row : {"wood       6  -1.500   1.049   [-2.601, -0.399]      -3.50     5    0.0172  sinusoidal",
                          "glass      3  -3.000   0.000   NA                       NA    NA        NA  sinusoidal",
                          "plastic    6   1.333   1.366   [-0.100, 2.767]        2.39     5    0.0624  neither (both)",
                          "metal      1   2.000      NA   NA"})
    EXPECT_NE(named.out.find(row), std::string::npos) << row << "\n" << named.out;
}

TEST(CliStatsAbScore, PlayedOrderAndMistakes) {
  const ms::test::TempDir dir;
  const std::string csv = dir.write("ab.csv", "participant,response,swapped,response_oriented\np1,2,1,-2\np2,-1,0,-1\np3,3,1,-3\n");
  const auto played = ms::test::run_cli("stats ab " + csv + " --task preference --score response", dir);
  ASSERT_EQ(played.exit_code, 0) << played.err;
  EXPECT_NE(played.err.find("'response' is each answer in the order played"), std::string::npos) << played.err;
  const auto oriented = ms::test::run_cli("stats ab " + csv + " --task preference --score response_oriented", dir);
  EXPECT_EQ(oriented.err.find("order played"), std::string::npos) << oriented.err;
  const std::string na = dir.write("na.csv", "participant,response_oriented\np1,2\np2,NA\n");
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"stats ab " + csv + " --task preference --subject participant", "--subject averages scores: give --score COL too"},
           {"stats ab " + csv + " --task preference --score response_oriented --subject listener", "ab.csv:1:1: missing column 'listener'"},
           {"stats ab " + csv + " --task preference --score response_oriented --options sinusoidal", "--options: name exactly the two options"},
           {"stats ab " + na + " --task preference --score response_oriented", "na.csv:3:"}}) {
    const auto r = ms::test::run_cli(args, dir);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(ms::test::count_lines(r.err), 1u) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
