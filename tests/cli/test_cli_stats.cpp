// modalstudy stats ... end to end: JSON equal to the R golden files, the printed table, and bad input
// ending in one line naming file:row:column with exit code 2.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "analysis/stats/confusion.hpp"
#include "synthesis/tidy_csv.hpp"
#include "support/test_util.hpp"

using namespace ms;

namespace {

const std::string kData = std::string(MODALSTUDY_TEST_DATA) + "/";

void expect_rel(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-6 * std::abs(expected) + 1e-12) << what;
}

struct BadCase {
  std::string args, expect;
};

void expect_bad(const test::TempDir& dir, const BadCase& c) {
  const auto r = test::run_cli(c.args, dir);
  EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find(c.expect), std::string::npos) << "expected '" << c.expect << "' in: " << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

}  // namespace

TEST(CliStatsAnova, JsonEqualsAfexGolden) {
  test::TempDir dir;
  const auto r = test::run_cli("stats anova " + kData + "anova/w2b.csv --dv rating --subject subject --within A,B "
                               "--between group --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["n_subjects"], 13);
  EXPECT_TRUE(j["notices"].empty());
  const TidyCsv golden = TidyCsv::read(kData + "anova/w2b_golden.csv");
  ASSERT_EQ(j["effects"].size(), golden.rows());
  for (std::size_t i = 0; i < golden.rows(); ++i) {
    const auto& e = j["effects"][i];
    EXPECT_EQ(e["effect"], golden.cell(i, 0));
    for (const char* key : {"df1", "df2", "F", "p", "p_gg", "p_hf", "ges", "pes"})
      expect_rel(e[key].get<double>(), golden.number(i, golden.column(key)), golden.cell(i, 0) + " " + key);
    for (const char* key : {"eps_gg", "eps_hf", "mauchly_w", "mauchly_p"}) {
      if (golden.cell(i, golden.column(key)) == "NA")
        EXPECT_TRUE(e[key].is_null()) << key;
      else
        expect_rel(e[key].get<double>(), golden.number(i, golden.column(key)), golden.cell(i, 0) + " " + key);
    }
  }
}

TEST(CliStatsAnova, AveragesRepeatedObservationsWithNoticeAndPrintsTable) {
  test::TempDir dir;
  const auto r = test::run_cli("stats anova " + kData + "anova/w2rep.csv --dv rating --subject subject --within A --within B",
                               dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("notice:"), std::string::npos);
  EXPECT_NE(r.err.find("aggregating with the mean"), std::string::npos);
  // The header of the published table and one row per effect, with the golden F printed to 4 digits.
  EXPECT_NE(r.out.find("Effect"), std::string::npos);
  EXPECT_NE(r.out.find("F value"), std::string::npos);
  EXPECT_NE(r.out.find("GG eps"), std::string::npos);
  EXPECT_NE(r.out.find("Mauchly"), std::string::npos);
  const TidyCsv golden = TidyCsv::read(kData + "anova/w2rep_golden.csv");
  for (std::size_t i = 0; i < golden.rows(); ++i) {
    char f[32];
    std::snprintf(f, sizeof f, "%.4g", golden.number(i, golden.column("F")));
    EXPECT_NE(r.out.find(golden.cell(i, 0) + " "), std::string::npos);
    EXPECT_NE(r.out.find(f), std::string::npos) << f << "\n" << r.out;
  }
}

TEST(CliStatsAnova, BadInputIsOneLineWithFileRowColumn) {
  test::TempDir dir;
  const std::string good = "subject,A,rating\ns1,a1,1\ns1,a2,2\ns2,a1,3\ns2,a2,5\n";
  const std::string ok = dir.write("ok.csv", good);
  const std::string nonnum = dir.write("nonnum.csv", "subject,A,rating\ns1,a1,1\ns1,a2,x7\ns2,a1,3\ns2,a2,5\n");
  const std::string missing_cell = dir.write("missing.csv", "subject,A,rating\ns1,a1,1\ns1,a2,2\ns2,a1,3\n");
  const std::string single = dir.write("single.csv", "subject,A,rating\ns1,a1,1\ns1,a2,2\n");
  const std::string ragged = dir.write("ragged.csv", "subject,A,rating\ns1,a1,1\ns1,a2\n");
  const std::string quoted = dir.write("quoted.csv", "subject,A,rating\ns1,\"a1\",1\ns1,\"a2,\n");
  const std::string between = dir.write("between.csv",
                                        "subject,A,g,rating\ns1,a1,x,1\ns1,a2,y,2\ns2,a1,x,3\ns2,a2,x,5\n");
  const std::string a = " --dv rating --subject subject --within A";
  const BadCase cases[] = {
      {"stats anova " + ok + " --dv score --subject subject --within A", "ok.csv:1:1: missing column 'score'"},
      {"stats anova " + ok + " --dv rating --subject subject --within B", "ok.csv:1:1: missing column 'B'"},
      {"stats anova " + nonnum + a, "nonnum.csv:3:7: column 'rating': expected a number, got 'x7'"},
      {"stats anova " + missing_cell + a, "missing.csv:4:1: subject 's2' has no observation for A=a2"},
      {"stats anova " + single + a, "single.csv:2:1: only one subject"},
      {"stats anova " + ragged + a, "ragged.csv:3:1: expected 3 cells"},
      {"stats anova " + quoted + a, "quoted.csv:3:4: unterminated quoted field"},
      {"stats anova " + between + a + " --between g", "between.csv:3:7: between factor 'g' changes within subject 's1'"},
      {"stats anova " + dir.file("nope.csv") + a, "nope.csv: no such file"},
      {"stats ttest " + ok + " --dv rating --group A --paired", "--paired needs --subject"},
      {"stats ttest " + missing_cell + " --dv rating --group A --paired --subject subject",
       "missing.csv:4:1: subject 's2' has no observation for A=a2"},
  };
  for (const auto& c : cases) expect_bad(dir, c);
}

TEST(CliStatsAnova, PosthocPairsEqualRPairwiseTTest) {
  test::TempDir dir;
  const auto r = test::run_cli("stats anova " + kData + "posthoc/data.csv --dv score --subject subject "
                               "--within method,material --between group --posthoc method,group "
                               "--p-adjust bonferroni --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["posthoc"].size(), 2u);
  const TidyCsv golden = TidyCsv::read(kData + "posthoc/golden.csv");
  int matched = 0;
  for (const auto& h : j["posthoc"]) {
    EXPECT_EQ(h["adjust"], "bonferroni");
    EXPECT_EQ(h["within"], h["factor"] == "method");
    for (const auto& pair : h["pairs"])
      for (std::size_t i = 0; i < golden.rows(); ++i) {
        const std::string a = golden.cell(i, golden.column("a")), b = golden.cell(i, golden.column("b"));
        const bool same = pair["a"] == a && pair["b"] == b, flipped = pair["a"] == b && pair["b"] == a;
        if (golden.cell(i, golden.column("factor")) != h["factor"] ||
            golden.cell(i, golden.column("adjust")) != "bonferroni" || !(same || flipped))
          continue;
        expect_rel(pair["p_adjusted"].get<double>(), golden.number(i, golden.column("p_adjusted")), a + "-" + b);
        expect_rel((same ? 1 : -1) * pair["mean_diff"].get<double>(), golden.number(i, golden.column("mean_diff")),
                   a + "-" + b);
        ++matched;
      }
  }
  EXPECT_EQ(matched, 6);
  const auto text = test::run_cli("stats anova " + kData + "posthoc/data.csv --dv score --subject subject "
                                  "--within method,material --posthoc method", dir);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("Pairwise paired t-tests of method (holm adjustment over 3 pairs"), std::string::npos)
      << text.out;
  expect_bad(dir, {"stats anova " + kData + "posthoc/data.csv --dv score --subject subject --within method "
                   "--posthoc colour",
                   "--posthoc 'colour' is not one of the --within or --between factors"});
}

TEST(CliStatsTTest, JsonEqualsRGolden) {
  test::TempDir dir;
  const TidyCsv golden = TidyCsv::read(kData + "anova/ttest_golden.csv");
  const std::string args[] = {
      "stats ttest " + kData + "anova/ttest_paired.csv --dv rating --group condition --paired --subject subject --json",
      "stats ttest " + kData + "anova/ttest_independent.csv --dv rating --group group --json",
      "stats ttest " + kData + "anova/ttest_independent.csv --dv rating --group group --student --json"};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto r = test::run_cli(args[i], dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    // The CLI orders levels by first appearance; the golden difference is before - after and
    // recorded - synthesised, so flip the sign when the file lists the other level first.
    const bool flipped = j["levels"][0] == "after" || j["levels"][0] == "synthesised";
    const double s = flipped ? -1.0 : 1.0;
    const std::string tag = golden.cell(i, 0);
    expect_rel(s * j["t"].get<double>(), golden.number(i, golden.column("t")), tag + " t");
    expect_rel(j["df"].get<double>(), golden.number(i, golden.column("df")), tag + " df");
    expect_rel(j["p"].get<double>(), golden.number(i, golden.column("p")), tag + " p");
    const double lo = flipped ? -j["ci"][1].get<double>() : j["ci"][0].get<double>();
    const double hi = flipped ? -j["ci"][0].get<double>() : j["ci"][1].get<double>();
    expect_rel(lo, golden.number(i, golden.column("ci_low")), tag + " ci_low");
    expect_rel(hi, golden.number(i, golden.column("ci_high")), tag + " ci_high");
    if (i == 0) {
      EXPECT_EQ(j["notices"].size(), 1u);
    }
  }
}

TEST(CliStatsConfusion, CompareJsonEqualsSklearnGolden) {
  test::TempDir dir;
  std::ifstream in(kData + "confusion/golden.json");
  const auto g = nlohmann::json::parse(in);
  const std::string d = kData + "confusion/";
  const auto r = test::run_cli("stats confusion " + d + "responses_recorded.csv --truth material --response answer "
                               "--labels wood,plastic,metal,porcelain,glass --compare " + d +
                               "responses_synthesised.csv --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["labels"], g["labels"]);
  EXPECT_EQ(j["counts"], g["recorded"]["counts"]);
  EXPECT_EQ(j["compare"]["counts"], g["synthesised"]["counts"]);
  for (const char* key : {"accuracy", "kappa", "chi2"}) {
    expect_rel(j[key].get<double>(), g["recorded"][key].get<double>(), key);
    expect_rel(j["compare"][key].get<double>(), g["synthesised"][key].get<double>(), key);
  }
  EXPECT_EQ(j["chi2_df"], g["recorded"]["chi2_df"]);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t k = 0; k < 5; ++k)
      expect_rel(j["row_percent"][i][k].get<double>(), g["recorded"]["row_percent"][i][k].get<double>(), "pct");
  expect_rel(j["frobenius"].get<double>(), g["recorded_vs_synthesised"]["frobenius"].get<double>(), "frobenius");
  for (std::size_t i = 0; i < 5; ++i) {
    expect_rel(j["recall_diff"][i]["ci_low"].get<double>(),
               g["recorded_vs_synthesised"]["recall_diff_ci"][i][0].get<double>(), "ci_low");
    expect_rel(j["recall_diff"][i]["ci_high"].get<double>(),
               g["recorded_vs_synthesised"]["recall_diff_ci"][i][1].get<double>(), "ci_high");
  }
}

TEST(CliStatsConfusion, WaldIntervalsAreSymmetricAsPropTest) {
  test::TempDir dir;
  const std::string d = kData + "confusion/";
  for (const std::string method : {"wald", "wald-cc"}) {
    const auto r = test::run_cli("stats confusion " + d + "responses_recorded.csv --truth material --response answer "
                                 "--labels wood,plastic,metal,porcelain,glass --compare " + d +
                                 "responses_synthesised.csv --interval " + method + " --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["interval"], method);
    for (std::size_t i = 0; i < 5; ++i) {
      const double x1 = j["counts"][i][i], x2 = j["compare"]["counts"][i][i];
      double n1 = 0, n2 = 0;
      for (std::size_t k = 0; k < 5; ++k) {
        n1 += j["counts"][i][k].get<double>();
        n2 += j["compare"]["counts"][i][k].get<double>();
      }
      const Interval expected = wald_difference(x1, n1, x2, n2, method == "wald-cc");
      expect_rel(j["recall_diff"][i]["ci_low"].get<double>(), expected.low, method + " low");
      expect_rel(j["recall_diff"][i]["ci_high"].get<double>(), expected.high, method + " high");
    }
  }
  const auto text = test::run_cli("stats confusion " + d + "responses_recorded.csv --truth material --response answer "
                                  "--compare " + d + "responses_synthesised.csv --interval wald-cc", dir);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("95% Wald (continuity-corrected) interval"), std::string::npos) << text.out;
  const auto bad = test::run_cli("stats confusion " + d + "responses_recorded.csv --truth material --response answer "
                                 "--interval score", dir);
  EXPECT_EQ(bad.exit_code, 2) << bad.err;  // a bad option is bad input: one line, exit 2
  EXPECT_EQ(test::count_lines(bad.err), 1u) << bad.err;
  EXPECT_NE(bad.err.find("--interval: score not in {newcombe,wald,wald-cc}"), std::string::npos) << bad.err;
}

TEST(CliStatsConfusion, DefaultLabelsAreSortedAndTablePrints) {
  test::TempDir dir;
  const auto r = test::run_cli("stats confusion " + kData + "confusion/responses_recorded.csv --truth material "
                               "--response answer", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Cohen's kappa"), std::string::npos);
  // Sorted labels: glass first; the glass row of the golden counts is its last row.
  const auto j = nlohmann::json::parse(
      test::run_cli("stats confusion " + kData + "confusion/responses_recorded.csv --truth material --response answer --json",
                    dir).out);
  EXPECT_EQ(j["labels"][0], "glass");
  EXPECT_EQ(j["labels"][4], "wood");
  std::ifstream in(kData + "confusion/golden.json");
  const auto g = nlohmann::json::parse(in);
  EXPECT_EQ(j["counts"][0][0], g["recorded"]["counts"][4][4]);  // glass -> glass
}

TEST(CliStatsConfusion, BadInput) {
  test::TempDir dir;
  const std::string f = dir.write("r.csv", "listener,material,answer\nL1,wood,wood\nL1,metal,gold\n");
  const BadCase cases[] = {
      {"stats confusion " + f + " --truth material --response reply", "r.csv:1:1: missing column 'reply'"},
      {"stats confusion " + f + " --truth material --response answer --labels wood,metal",
       "r.csv:3:10: column 'answer': label 'gold' is not in --labels"},
      {"stats confusion " + f + " --truth material --response answer --compare " + dir.file("none.csv"),
       "none.csv: no such file"},
  };
  for (const auto& c : cases) expect_bad(dir, c);
}

TEST(CliStatsMushra, JsonEqualsRGolden) {
  test::TempDir dir;
  const auto r = test::run_cli("stats mushra " + kData + "mushra/results.csv --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["n_assessors"], 12);
  EXPECT_EQ(j["n_included"], 11);
  EXPECT_EQ(j["anchors"].size(), 2u);  // anchor35, anchor70 found by name
  for (const auto& a : j["assessors"]) {
    EXPECT_EQ(a["excluded"].get<bool>(), a["subject"] == "P03") << a;
    EXPECT_EQ(a["anchor_fails"].get<bool>(), a["subject"] == "P09") << a;
  }
  const TidyCsv golden = TidyCsv::read(kData + "mushra/summary_golden.csv");
  for (std::size_t i = 0; i < 6; ++i) {  // the ALL rows
    const auto& c = *std::find_if(j["conditions"].begin(), j["conditions"].end(),
                                  [&](const auto& x) { return x["condition"] == golden.cell(i, 1); });
    for (const char* key : {"mean", "sd", "ci_low", "ci_high"})
      expect_rel(c[key].get<double>(), golden.number(i, golden.column(key)), golden.cell(i, 1) + " " + key);
  }
  EXPECT_EQ(j["items"].size(), 8u);
  EXPECT_EQ(j["notices"].size(), 1u);
  // --screen-anchors also drops the assessor who rated the mid anchor above 90.
  const auto s = nlohmann::json::parse(
      test::run_cli("stats mushra " + kData + "mushra/results.csv --anchor anchor70 --screen-anchors --json", dir).out);
  EXPECT_EQ(s["n_included"], 10);
}

TEST(CliStatsBs1116, JsonEqualsSciPyGoldenAndTextNamesTheScale) {
  test::TempDir dir;
  const auto r = test::run_cli("stats bs1116 " + kData + "bs1116/grades.csv --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const TidyCsv golden = TidyCsv::read(kData + "bs1116/summary_golden.csv");
  ASSERT_EQ(j["conditions"].size(), golden.rows());
  for (std::size_t i = 0; i < golden.rows(); ++i) {
    EXPECT_EQ(j["conditions"][i]["condition"], golden.cell(i, 0));
    expect_rel(j["conditions"][i]["mean_diffgrade"].get<double>(), golden.number(i, 2), golden.cell(i, 0));
    expect_rel(j["conditions"][i]["ci_low"].get<double>(), golden.number(i, 4), golden.cell(i, 0));
  }
  EXPECT_EQ(j["assessors"].size(), 8u);
  const auto text = test::run_cli("stats bs1116 " + kData + "bs1116/grades.csv", dir);
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("condition - hidden reference"), std::string::npos) << text.out;
  EXPECT_NE(text.err.find("averaged per condition"), std::string::npos) << text.err;
  const auto bad = test::run_cli("stats bs1116 " + dir.write("b.csv", "participant,condition,diffgrade\nL1,c,9\n"), dir);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("b.csv:2:"), std::string::npos) << bad.err;
}

TEST(CliStatsMushra, BadInput) {
  test::TempDir dir;
  const std::string f = dir.write("m.csv", "participant,trial,condition,rating\nP1,t1,reference,100\nP1,t1,codec,101\n");
  const std::string g = dir.write("n.csv", "participant,trial,condition,rating\nP1,t1,ref,100\nP1,t1,codec,50\n");
  const BadCase cases[] = {
      {"stats mushra " + f, "m.csv:3:13: column 'rating': rating 101 outside the MUSHRA scale 0-100"},
      {"stats mushra " + g, "n.csv:1:1: no condition named 'reference'"},
      {"stats mushra " + g + " --reference ref --anchor lp", "--anchor: no condition named 'lp'"},
      {"stats mushra " + f + " --rating score", "m.csv:1:1: missing column 'score'"},
  };
  for (const auto& c : cases) expect_bad(dir, c);
}

namespace {
double golden_cell(const std::string& file, std::size_t row, const char* col) {
  const TidyCsv g = TidyCsv::read(kData + "psychophysics/" + file);
  return g.number(row, g.column(col));
}
}  // namespace

TEST(CliStatsAb, ForcedChoiceDetectionAndPreference) {
  test::TempDir dir;
  // 2AFC: listener A 15/20 correct, listener B 20/20 (perfect: d' uses 1 - 1/(2N)).
  std::string afc = "participant,trial,correct\n";
  for (int i = 0; i < 20; ++i) afc += "A," + std::to_string(i) + "," + (i < 15 ? "1" : "0") + "\n";
  for (int i = 0; i < 20; ++i) afc += "B," + std::to_string(i) + ",true\n";
  auto r = test::run_cli("stats ab " + dir.write("afc.csv", afc) + " --task 2afc --correct correct --by participant --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["groups"].size(), 2u);
  expect_rel(j["groups"][0]["p_above_chance"].get<double>(), golden_cell("binom_golden.csv", 1, "p"), "15/20 greater");
  expect_rel(j["groups"][0]["dprime"].get<double>(), std::sqrt(2.0) * 0.67448975019608171, "2afc d' = sqrt2 z(.75)");
  expect_rel(j["groups"][1]["p_above_chance"].get<double>(), golden_cell("binom_golden.csv", 4, "p"), "20/20 greater");
  expect_rel(j["groups"][1]["dprime"].get<double>(), std::sqrt(2.0) * 1.959963984540054, "d' at 1 - 1/40");
  EXPECT_EQ(j["notices"].size(), 1u);

  // ABX: 28/40 correct is p_c = 0.7 (golden row 2 of dprime_golden.csv).
  std::string abx = "trial,ok\n";
  for (int i = 0; i < 40; ++i) abx += std::to_string(i) + "," + (i % 10 < 7 ? "correct" : "incorrect") + "\n";
  r = test::run_cli("stats ab " + dir.write("abx.csv", abx) + " --task abx --correct ok --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  expect_rel(j["groups"][0]["dprime"].get<double>(), golden_cell("dprime_golden.csv", 2, "dprime_abx"), "abx d'");

  // Same-different: H = 15/20, F = 4/20 (golden row 1 of same_different_golden.csv).
  std::string sd = "pair,answer\n";
  for (int i = 0; i < 20; ++i) sd += std::string("different,") + (i < 15 ? "different" : "same") + "\n";
  for (int i = 0; i < 20; ++i) sd += std::string("same,") + (i < 4 ? "different" : "same") + "\n";
  r = test::run_cli("stats ab " + dir.write("sd.csv", sd) + " --task same-different --stimulus pair --response answer --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  expect_rel(j["groups"][0]["dprime"].get<double>(), golden_cell("same_different_golden.csv", 1, "dprime"), "s-d d'");
  expect_rel(j["groups"][0]["criterion_k"].get<double>(), golden_cell("same_different_golden.csv", 1, "k"), "s-d k");

  // Preference: 7 x A, 3 x B, 2 ties -> two-sided exact p of 7/10 (golden row 0); scores vs 0.
  const std::string pref = dir.write("pref.csv", "choice,score\nA,2\nA,1\nA,3\nB,-1\nA,2\nnone,0\nA,1\nB,-2\nA,2\nnone,0\nB,-1\nA,1\n");
  r = test::run_cli("stats ab " + pref + " --task preference --choice choice --options A,B --score score --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["groups"][0]["ties"], 2);
  expect_rel(j["groups"][0]["p"].get<double>(), golden_cell("binom_golden.csv", 0, "p"), "preference p");
  expect_rel(j["groups"][0]["score"]["mean"].get<double>(), 8.0 / 12.0, "mean score");

  // Bad values name the cell.
  expect_bad(dir, {"stats ab " + dir.write("bad.csv", "correct\n1\nmaybe\n") + " --task 2afc --correct correct",
                   "bad.csv:3:1: column 'correct': expected 1/0"});
  expect_bad(dir, {"stats ab " + pref + " --task 2afc", "--task 2afc needs --correct COL"});
}

TEST(CliStatsStaircase, ThresholdPerTrack) {
  test::TempDir dir;
  // Track "p1": levels 10 8 6 7 8 7 7 5 6 (reversals 6, 8, 5), rows shuffled, ordered by --trial.
  // Track "p2": levels 4 2 4 2 4 (reversals 2, 4, 2).
  const std::string f = dir.write("s.csv",
                                  "who,trial,level\np1,3,7\np1,1,8\np2,0,4\np1,0,10\np1,8,6\np1,2,6\np2,1,2\np1,4,8\n"
                                  "p1,5,7\np2,2,4\np1,6,7\np2,3,2\np1,7,5\np2,4,4\n");
  const auto r = test::run_cli("stats staircase " + f + " --level level --track who --trial trial --reversals 2 --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["tracks"].size(), 2u);
  EXPECT_EQ(j["tracks"][0]["reversal_levels"], nlohmann::json({6.0, 8.0, 5.0}));
  EXPECT_DOUBLE_EQ(j["tracks"][0]["threshold"].get<double>(), 6.5);
  EXPECT_DOUBLE_EQ(j["tracks"][1]["threshold"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(j["overall"]["mean"].get<double>(), 4.75);
  // Without a next_level column the last trial's reversal cannot be seen: said once.
  ASSERT_EQ(j["notices"].size(), 1u);
  EXPECT_NE(j["notices"][0].get<std::string>().find("no column 'next_level'"), std::string::npos);
}

TEST(CliStatsMds, ClassicalJsonEqualsCmdscaleAndWritesPoints) {
  test::TempDir dir;
  const auto r = test::run_cli("stats mds " + kData + "mds/dissimilarity.csv --dims 2 --method classical --json -o " +
                               dir.file("points.csv"), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const TidyCsv golden = TidyCsv::read(kData + "mds/classical_points_golden.csv");
  const TidyCsv written = TidyCsv::read(dir.file("points.csv"));
  ASSERT_EQ(j["points"].size(), golden.rows());
  ASSERT_EQ(written.rows(), golden.rows());
  for (std::size_t k = 0; k < 2; ++k) {
    // Column signs are arbitrary: align on the first row.
    const double sign = (j["points"][0][k].get<double>() * golden.number(0, k + 1)) < 0 ? -1.0 : 1.0;
    for (std::size_t i = 0; i < golden.rows(); ++i) {
      EXPECT_NEAR(sign * j["points"][i][k].get<double>(), golden.number(i, k + 1), 1e-9);
      EXPECT_EQ(written.number(i, k + 1), j["points"][i][k].get<double>());
    }
  }
  EXPECT_EQ(j["labels"][0], golden.cell(0, 0));
  // SMACOF lowers stress-1 below the classical solution's.
  const auto s = nlohmann::json::parse(
      test::run_cli("stats mds " + kData + "mds/dissimilarity.csv --method smacof --starts 2 --json", dir).out);
  EXPECT_LT(s["stress1"].get<double>(), j["stress1"].get<double>());
}

// R's eurodist as R's write.csv(as.matrix(eurodist)) and pandas' to_csv() write it (header starting with an
// empty cell; BOM, CRLF and quotes in the third file): loads and maps as R's cmdscale does.
TEST(CliStatsMds, EurodistWrittenByRAndPandasMapsAsCmdscale) {
  test::TempDir dir;
  const TidyCsv golden = TidyCsv::read(kData + "csv/eurodist_cmdscale_golden.csv");
  const TidyCsv eig = TidyCsv::read(kData + "csv/eurodist_eig_golden.csv");
  for (const char* file : {"eurodist_r.csv", "eurodist_pandas.csv", "eurodist_pandas_bom_quoted.csv"}) {
    const auto r = test::run_cli("stats mds " + kData + "csv/" + file + " --dims 2 --method classical --json", dir);
    ASSERT_EQ(r.exit_code, 0) << file << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["labels"].size(), 21u) << file;
    EXPECT_EQ(j["labels"][10], "Hook of Holland") << file;
    for (std::size_t k = 0; k < 2; ++k) {
      expect_rel(j["eigenvalues"][k].get<double>(), eig.number(k, 0), std::string(file) + " eigenvalue");
      const double sign = (j["points"][0][k].get<double>() * golden.number(0, k + 1)) < 0 ? -1.0 : 1.0;
      for (std::size_t i = 0; i < golden.rows(); ++i)
        EXPECT_NEAR(sign * j["points"][i][k].get<double>(), golden.number(i, k + 1), 1e-6) << file << " " << i;
    }
  }
}

TEST(CliStatsMds, BadInput) {
  test::TempDir dir;
  const std::string asym = dir.write("asym.csv", "s,a,b,c\na,0,1,2\nb,1,0,3\nc,2,4,0\n");
  const std::string label = dir.write("label.csv", "s,a,b,c\na,0,1,2\nx,1,0,3\nc,2,3,0\n");
  const BadCase cases[] = {
      {"stats mds " + asym + " -o " + dir.file("never.csv"), "asym.csv:4:5: not symmetric: 4 here but 3 for (b, c)"},
      {"stats mds " + label, "label.csv:3:1: row label 'x' differs from column 3 'b'"},
      {"stats mds " + asym + " --pairs a,b", "--pairs: give three columns"},
  };
  for (const auto& c : cases) expect_bad(dir, c);
  EXPECT_FALSE(std::filesystem::exists(dir.file("never.csv")));
}

// stats magnitude on the seeded Experiment-3-shaped study (tests/data/magnitude/make_golden.py):
// the JSON matrix equals numpy's, the map's stress is no worse than SMACOF from the classical start
// alone, and -o writes a square matrix that `stats mds` reads back to the same map.
TEST(CliStatsMagnitude, JsonEqualsNumpyGoldenAndMatrixRoundTrips) {
  test::TempDir dir;
  const std::string matrix = dir.file("matrix.csv");
  const auto r = test::run_cli("stats magnitude " + kData + "magnitude/ratings.csv --subject listener --a first "
                               "--b second --rating rating --modulus-a real --modulus-b m1 --dims 2 --json -o " + matrix,
                               dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::ifstream in(kData + "magnitude/golden.json");
  const auto g = nlohmann::json::parse(in);
  const auto labels = j["labels"].get<std::vector<std::string>>();
  const auto glabels = g["labels"].get<std::vector<std::string>>();
  ASSERT_EQ(labels.size(), 12u);
  auto gi = [&](const std::string& l) { return std::size_t(std::find(glabels.begin(), glabels.end(), l) - glabels.begin()); };
  for (std::size_t a = 0; a < 12; ++a)
    for (std::size_t b = 0; b < 12; ++b)
      expect_rel(j["dissimilarity"][a][b].get<double>(), g["dissimilarity_modulus"][gi(labels[a])][gi(labels[b])].get<double>(),
                 labels[a] + "-" + labels[b]);
  EXPECT_EQ(j["normalisation"], "modulus");
  ASSERT_EQ(j["listeners"].size(), 8u);
  for (std::size_t l = 0; l < 8; ++l) {
    EXPECT_EQ(j["listeners"][l]["subject"], g["listeners"][l]);
    expect_rel(j["listeners"][l]["factor"].get<double>(), g["factor_modulus"][l].get<double>(), "factor");
  }
  ASSERT_EQ(j["coords"].size(), 12u);
  ASSERT_EQ(j["coords"][0].size(), 2u);
  const double s1 = j["stress1"].get<double>();
  // The CLI stops at a relative stress change of 1e-8 (the golden at 1e-13): allow that slack.
  EXPECT_LE(s1, g["smacof_classical_start"]["stress1"].get<double>() + 1e-6);
  EXPECT_GT(s1, 0.02);  // noisy ratings do not fit a plane exactly
  // Round trip: the written matrix, scaled by stats mds with the same seed and starts, gives the same stress.
  const auto mds = test::run_cli("stats mds " + matrix + " --method smacof --json", dir);
  ASSERT_EQ(mds.exit_code, 0) << mds.err;
  EXPECT_NEAR(nlohmann::json::parse(mds.out)["stress1"].get<double>(), s1, 1e-12);
  // Without a modulus: geometric-mean normalisation.
  const auto gm = test::run_cli("stats magnitude " + kData + "magnitude/ratings.csv --subject listener --a first "
                                "--b second --rating rating --json", dir);
  ASSERT_EQ(gm.exit_code, 0) << gm.err;
  const auto jg = nlohmann::json::parse(gm.out);
  EXPECT_EQ(jg["normalisation"], "geometric_mean");
  expect_rel(jg["dissimilarity"][0][1].get<double>(),
             g["dissimilarity_geometric"][gi(labels[0])][gi(labels[1])].get<double>(), "geometric");
  // The printed table names the normalisation and the stress.
  const auto text = test::run_cli("stats magnitude " + kData + "magnitude/ratings.csv --subject listener --a first "
                                  "--b second --rating rating --modulus-a real --modulus-b m1", dir);
  EXPECT_NE(text.out.find("the modulus pair (real, m1) = 10"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("stress-1 = "), std::string::npos);
}

TEST(CliStatsMagnitude, BadInput) {
  test::TempDir dir;
  const std::string zero = dir.write("zero.csv", "subject,a,b,rating\nA,x,y,1\nA,x,z,0\nA,y,z,2\n");
  const std::string gap = dir.write("gap.csv", "subject,a,b,rating\nA,x,y,1\nA,x,z,3\nA,w,x,2\n");
  const BadCase cases[] = {
      {"stats magnitude " + zero + " -o " + dir.file("never.csv"),
       "zero.csv:3:7: column 'rating': magnitude estimates must be positive (got 0)"},
      {"stats magnitude " + gap + " -o " + dir.file("never.csv"), "gap.csv:1:1: the pair (y, z) was never rated"},
      {"stats magnitude " + gap + " --rating score", "gap.csv:1:"},
      {"stats magnitude " + gap + " --modulus-a x", "--modulus-a and --modulus-b go together"},
      {"stats magnitude " + gap + " --modulus-a x --modulus-b q", "modulus token 'q' does not occur"},
  };
  for (const auto& c : cases) expect_bad(dir, c);
  EXPECT_FALSE(std::filesystem::exists(dir.file("never.csv")));
}

// --plot draws the picture of a statistic beside its numbers; a bad extension fails before any work.
TEST(CliStatsPlot, ConfusionMdsAndMushraDrawPictures) {
  test::TempDir dir;
  const std::string data = std::string(MODALSTUDY_TEST_DATA) + "/";
  const struct {
    std::string args, file;
  } cases[] = {
      {"stats confusion " + data + "confusion/responses_recorded.csv --truth material --response answer",
       "conf.png"},
      {"stats mds " + data + "mds/dissimilarity.csv --method smacof", "map.svg"},
      {"stats mushra " + data + "mushra/results.csv", "boxes.png"},
  };
  for (const auto& c : cases) {
    const auto r = test::run_cli(c.args + " --plot " + dir.file(c.file), dir);
    EXPECT_EQ(r.exit_code, 0) << c.args << "\n" << r.err;
    ASSERT_TRUE(std::filesystem::exists(dir.file(c.file))) << c.args;
    EXPECT_GT(std::filesystem::file_size(dir.file(c.file)), 2000u) << c.args;
    const auto bad = test::run_cli(c.args + " --plot " + dir.file("x.gif"), dir);
    EXPECT_EQ(bad.exit_code, 2) << c.args;
    EXPECT_NE(bad.err.find("x.gif"), std::string::npos) << bad.err;
    EXPECT_TRUE(bad.out.empty()) << "fails before printing statistics";
  }
}

// The 2002 study's Experiment 1 as trial series (a_v from 20 dB down in 1 dB steps until a difference
// is heard). The series are written by hand FROM Table 1, so this checks that the method of limits
// reads a series as the paper describes (the last "same" level), not the paper's result: it cannot
// disagree with Table 1. Only a lab's own series can.
TEST(CliStatsLimits, VanDenDoel2002Experiment1) {
  test::TempDir dir;
  const auto r = test::run_cli("stats limits " + kData + "vandendoel2002/experiment1_series.csv --level av_db "
                               "--response answer --track object,subject --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["tracks"].size(), 16u);
  EXPECT_EQ(j["median"], 16.0);
  const TidyCsv table1 = TidyCsv::read(kData + "vandendoel2002/table1_av.csv");
  std::map<std::string, double> expected;
  for (std::size_t row = 0; row < table1.rows(); ++row)
    expected[table1.cell(row, table1.column("object")) + "/" + table1.cell(row, table1.column("subject"))] =
        table1.number(row, table1.column("av_db"));
  for (const auto& t : j["tracks"]) {
    const std::string key = t["track"].get<std::string>();
    ASSERT_TRUE(expected.count(key)) << key;
    EXPECT_EQ(t["threshold"].get<double>(), expected[key]) << key;
  }
  // A level that does not fall is named with its row and column.
  const std::string bad = dir.write("bad.csv", "subject,av_db,answer\n1,20,same\n1,20,different\n");
  const auto b = test::run_cli("stats limits " + bad + " --level av_db --response answer --track subject", dir);
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("bad.csv:3:3"), std::string::npos) << b.err;
}

// Intervals past the 0-100 scale are reported as computed and marked, with a notice.
TEST(CliStatsMushra, IntervalPastTheScaleIsMarkedNotClipped) {
  test::TempDir dir;
  // ref: 100, 100, 90 -> mean 96.67, sd 5.774, t(2; .975) = 4.303: [82.32, 111.01].
  const std::string f = dir.write("m.csv", "participant,trial,condition,rating\n"
                                           "a,1,ref,100\na,1,low,20\nb,1,ref,100\nb,1,low,30\nc,1,ref,90\nc,1,low,25\n");
  const auto j = test::run_cli("stats mushra " + f + " --reference ref --json", dir);
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto out = nlohmann::json::parse(j.out);
  const auto& ref = out["conditions"][0];
  ASSERT_EQ(ref["condition"], "ref");
  expect_rel(ref["ci_high"].get<double>(), 96.666666666666671 + 4.302652729749464 * std::sqrt(100.0 / 3.0) / std::sqrt(3.0),
             "ci_high as computed");
  EXPECT_GT(ref["ci_high"].get<double>(), 100.0);
  EXPECT_TRUE(ref["ci_past_scale"].get<bool>());
  EXPECT_FALSE(out["conditions"][1]["ci_past_scale"].get<bool>());
  const auto t = test::run_cli("stats mushra " + f + " --reference ref", dir);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("111.01]*"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("* the interval passes the 0-100 scale"), std::string::npos) << t.out;
  EXPECT_NE(t.err.find("pass the 0-100 scale; reported as computed"), std::string::npos) << t.err;
  EXPECT_EQ(t.out.find("nan"), std::string::npos) << t.out;
}

// No NaN, inf or raw library message with exit 0: undefined statistics are refused in one line.
TEST(CliStatsUndefined, ConstantDataAndZeroErrorAreRefused) {
  test::TempDir dir;
  const std::string same = dir.write("same.csv", "s,g,v\n1,a,2\n1,b,1\n2,a,3\n2,b,2\n3,a,4\n3,b,3\n");
  expect_bad(dir, {"stats ttest " + same + " --dv v --group g --paired --subject s",
                   "same.csv: column 'v': the differences are all equal (standard deviation 0)"});
  const std::string flat = dir.write("flat.csv", "g,v\na,1\na,1\nb,2\nb,2\n");
  expect_bad(dir, {"stats ttest " + flat + " --dv v --group g", "flat.csv: column 'v': both groups are constant"});
  expect_bad(dir, {"stats anova " + same + " --dv v --subject s --within g",
                   "same.csv: column 'v': effect g: the error sum of squares is 0"});
  // 1e300 data: computed (not a Boost error).
  const std::string big = dir.write("big.csv", "g,v\na,1e300\na,2e300\na,3e300\nb,1\nb,2\nb,3\n");
  const auto r = test::run_cli("stats ttest " + big + " --dv v --group g --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // Welch: difference 2e300, se = sqrt(1e600/3 + 1/3) = 1e300/sqrt(3) to double precision: t = 2 sqrt(3).
  expect_rel(j["t"].get<double>(), 2.0 * std::sqrt(3.0), "t");
  EXPECT_TRUE(j["ci"][0].is_number());
  EXPECT_TRUE(j["ci"][1].is_number());
}
