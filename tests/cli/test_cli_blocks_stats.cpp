// The statistics of the token and change-point blocks and Fig. 4's difference curve, end to end through
// the command line on tables written by hand: Table 2's layout with every sequence's ceiling and share
// (and the note that counts of unequal ceilings are not comparable), Fig. 5.4's counts per value and
// object, `stats magnitude --vs --offset --x`, and bad input as one located line with exit 2.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "support/test_util.hpp"

using namespace ms;

namespace {

// The export's columns; two participants, sequences vase (5 tokens) and bowl (3 tokens).
// p1 vase: same, different, same, different -> 5, 3, 1 = 3 of 5; p1 bowl: different, different -> 3 of 3.
// p2 vase: all same -> 1 of 5; p2 bowl: same, different -> 2 of 3.
const char* kTokens =
    "study,participant,session,autopilot,block,trial,stimulus,step,reference,comparison,response,different,distinguished,tokens,object\n"
    "s,p1,1,0,tok-vase,0,vase,0,5,4,same,0,3,5,vase\n"
    "s,p1,1,0,tok-vase,0,vase,1,5,3,different,1,3,5,vase\n"
    "s,p1,1,0,tok-vase,0,vase,2,3,2,same,0,3,5,vase\n"
    "s,p1,1,0,tok-vase,0,vase,3,3,1,different,1,3,5,vase\n"
    "s,p1,1,0,tok-bowl,0,bowl,0,3,2,different,1,3,3,bowl\n"
    "s,p1,1,0,tok-bowl,0,bowl,1,2,1,different,1,3,3,bowl\n"
    "s,p2,2,0,tok-vase,0,vase,0,5,4,same,0,1,5,vase\n"
    "s,p2,2,0,tok-vase,0,vase,1,5,3,same,0,1,5,vase\n"
    "s,p2,2,0,tok-vase,0,vase,2,5,2,same,0,1,5,vase\n"
    "s,p2,2,0,tok-vase,0,vase,3,5,1,same,0,1,5,vase\n"
    "s,p2,2,0,tok-bowl,0,bowl,0,3,2,same,0,2,3,bowl\n"
    "s,p2,2,0,tok-bowl,0,bowl,1,3,1,different,1,2,3,bowl\n";

}  // namespace

TEST(CliStatsTokens, Table2LayoutWithCeilingsAndShares) {
  test::TempDir dir;
  const std::string csv = dir.write("tokens.csv", kTokens);
  const auto r = test::run_cli("stats tokens " + csv, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("tok-vase"), std::string::npos) << r.out;
  // participant rows, then the ceilings 5 and 3 and the median shares (3/5 + 1/5) / 2 = 40 %, (1 + 2/3) / 2 = 83 %
  EXPECT_NE(r.out.find("p1                     3           3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ceiling                5           3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("median share        40 %        83 %"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not comparable"), std::string::npos) << r.out;
  // The sequence named by the stimuli's factor instead of the block.
  const auto j = test::run_cli("stats tokens " + csv + " --condition object --json", dir);
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto out = nlohmann::json::parse(j.out);
  ASSERT_EQ(out["conditions"].size(), 2u);
  EXPECT_EQ(out["conditions"][0]["condition"], "vase");
  EXPECT_EQ(out["conditions"][0]["tokens_min"], 5);
  EXPECT_DOUBLE_EQ(out["conditions"][0]["median"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(out["participants"][1]["cells"]["bowl"]["distinguished"].get<double>(), 2.0);
  EXPECT_NEAR(out["participants"][1]["cells"]["bowl"]["share"].get<double>(), 2.0 / 3.0, 1e-12);
}

TEST(CliStatsTokens, BadInputIsOneLocatedLine) {
  test::TempDir dir;
  std::string bad = kTokens;
  bad.replace(bad.find("vase,1,5,3,different"), 20, "vase,1,4,3,different");  // a reference the answers do not give
  const std::string csv = dir.write("tokens.csv", bad);
  const auto r = test::run_cli("stats tokens " + csv, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find(csv + ":3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("make 5 modes the reference"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  const auto missing = test::run_cli("stats tokens " + csv + " --condition material", dir);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("'material'"), std::string::npos) << missing.err;
}

TEST(CliStatsChangepoint, Figure54CountsPerValueAndObject) {
  test::TempDir dir;
  std::string csv = "study,participant,session,autopilot,block,trial,stimulus,parameter,position,value,marked,marks,object\n";
  // jug: p1 marks 1600, p2 marks 1600 and 2200; pot: p1 marks nothing.
  const auto sweep = [&](const std::string& who, const std::string& trial, const std::string& object, const char* marked) {
    const int values[] = {1000, 1600, 2200};
    for (int i = 0; i < 3; ++i)
      csv += "s," + who + ",1,0,q," + trial + "," + object + std::to_string(i) + ",Q," + std::to_string(i) + "," +
             std::to_string(values[i]) + "," + marked[i] + ",0," + object + "\n";
  };
  sweep("p1", "0", "jug", "010");
  sweep("p2", "0", "jug", "011");
  sweep("p1", "1", "pot", "000");
  const std::string path = dir.write("changepoint.csv", csv);
  const auto r = test::run_cli("stats changepoint " + path + " --by object --top 1", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // value rows, columns jug, pot and all
  EXPECT_NE(r.out.find("1600            2      0      2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2200            1      0      1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sweeps          2      1      3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("jug    1600 (2/2)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pot    no marks"), std::string::npos) << r.out;
  const auto j = test::run_cli("stats changepoint " + path + " --by object --json", dir);
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto out = nlohmann::json::parse(j.out);
  ASSERT_EQ(out["groups"].size(), 3u);
  EXPECT_EQ(out["groups"][2]["group"], "all");
  EXPECT_EQ(out["groups"][0]["most_chosen"], nlohmann::json::parse("[1600.0, 2200.0]"));
  // A mark that is not 0/1: one located line, exit 2.
  std::string bad = csv;
  bad.replace(bad.rfind(",0,0,pot"), 8, ",x,0,pot");
  const std::string bad_path = dir.write("bad.csv", bad);
  const auto e = test::run_cli("stats changepoint " + bad_path, dir);
  EXPECT_EQ(e.exit_code, 2);
  EXPECT_EQ(test::count_lines(e.err), 1u) << e.err;
  EXPECT_NE(e.err.find(bad_path + ":10:"), std::string::npos) << e.err;
}

TEST(CliStatsMagnitude, DifferenceToTheReferenceAsFigure4) {
  test::TempDir dir;
  // The export's magnitude.csv columns (and the factor `modes`, written on identical pairs).
  const std::string csv = dir.write(
      "magnitude.csv",
      "participant,block,first,second,value,modulus_a,modulus_b,modulus_value,modes\n"
      "p1,m,real,m1,10,real,m1,10,\n" "p1,m,m9,real,3,real,m1,10,\n" "p1,m,m1,m1,1,real,m1,10,1\n"
      "p1,m,m9,m9,1,real,m1,10,9\n" "p1,m,m1,m9,6,real,m1,10,\n"
      "p2,m,m1,real,9,real,m1,10,\n" "p2,m,real,m9,2,real,m1,10,\n" "p2,m,m1,m1,1,real,m1,10,1\n"
      "p2,m,m9,m9,2,real,m1,10,9\n" "p2,m,m1,m9,5,real,m1,10,\n");
  const std::string columns = " --subject participant --a first --b second --rating value";
  const auto r = test::run_cli("stats magnitude " + csv + columns + " --vs real --offset -1 --x modes --json -o " +
                                   dir.file("fig4.csv"), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["points"].size(), 2u);
  EXPECT_EQ(j["points"][0]["x"], "1");
  EXPECT_DOUBLE_EQ(j["points"][0]["difference"].get<double>(), 8.5);  // (10 - 1 + 9 - 1) / 2
  EXPECT_EQ(j["points"][1]["x"], "9");
  EXPECT_DOUBLE_EQ(j["points"][1]["difference"].get<double>(), 1.5);  // (3 - 1 + 2 - 1) / 2
  std::ifstream curve(dir.file("fig4.csv"));
  std::string header;
  std::getline(curve, header);
  EXPECT_EQ(header, "modes,token,listeners,difference,sd\r");  // the one CSV writer ends lines with CRLF
  const auto plot = test::run_cli("plot lines " + dir.file("fig4.csv") + " --x modes --y difference -o " +
                                      dir.file("fig4.png"), dir);
  EXPECT_EQ(plot.exit_code, 0) << plot.err;
  // --x without --vs, and a reference nobody rated: one line, exit 2.
  const auto lonely = test::run_cli("stats magnitude " + csv + columns + " --x modes", dir);
  EXPECT_EQ(lonely.exit_code, 2);
  EXPECT_NE(lonely.err.find("belong to --vs"), std::string::npos) << lonely.err;
  const auto unknown = test::run_cli("stats magnitude " + csv + columns + " --vs recording", dir);
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(test::count_lines(unknown.err), 1u) << unknown.err;
  EXPECT_NE(unknown.err.find("no row rates the reference 'recording'"), std::string::npos) << unknown.err;
}
