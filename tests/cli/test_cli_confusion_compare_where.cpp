// `stats confusion --compare FILE --compare-where COL=VALUE`: two conditions of one export compared in one
// call (Ren et al. 2013's recorded and synthesised clips, Tables III-V): --where selects the first
// matrix's rows, --compare-where the second's from the --compare file; without it the second file
// takes --where's filters as before.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_util.hpp"

namespace {

const std::string kTable =
    "participant,condition,truth,response\n"
    "p1,recorded,metal,metal\np1,recorded,wood,wood\np1,recorded,glass,metal\n"
    "p1,synthesised,metal,metal\np1,synthesised,wood,plastic\np1,synthesised,glass,glass\np1,synthesised,plastic,plastic\n"
    "p2,recorded,metal,glass\np2,recorded,wood,wood\np2,recorded,glass,glass\n"
    "p2,synthesised,metal,metal\np2,synthesised,wood,wood\np2,synthesised,glass,glass\np2,synthesised,plastic,wood\n";

int count(const nlohmann::json& confusion, std::size_t truth, std::size_t response) {
  return confusion["counts"][truth][response].get<int>();
}

TEST(CliConfusionCompareWhere, TwoConditionsOfOneFile) {
  const ms::test::TempDir dir;
  const std::string f = dir.write("identify.csv", kTable);
  const auto r = ms::test::run_cli("stats confusion '" + f + "' --truth truth --response response --labels wood,plastic,metal,glass "
                                   "--where condition=recorded --compare '" + f + "' --compare-where condition=synthesised --json", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // recorded: 6 answers, no plastic row; synthesised: 8 answers
  int recorded = 0, synthesised = 0;
  for (std::size_t t = 0; t < 4; ++t)
    for (std::size_t a = 0; a < 4; ++a) recorded += count(j, t, a), synthesised += count(j["compare"], t, a);
  EXPECT_EQ(recorded, 6);
  EXPECT_EQ(synthesised, 8);
  EXPECT_EQ(count(j, 2, 3), 1);             // recorded metal heard as glass (p2)
  EXPECT_EQ(count(j["compare"], 1, 0), 1);  // synthesised plastic heard as wood (p2)
  // Without --compare-where both sides take --where: the same matrix twice, difference 0.
  const auto same = ms::test::run_cli("stats confusion '" + f + "' --truth truth --response response --where condition=recorded "
                                      "--compare '" + f + "' --json", dir);
  ASSERT_EQ(same.exit_code, 0) << same.err;
  EXPECT_EQ(nlohmann::json::parse(same.out)["frobenius"].get<double>(), 0.0);
}

TEST(CliConfusionCompareWhere, NeedsCompareAndAColumnThatExists) {
  const ms::test::TempDir dir;
  const std::string f = dir.write("identify.csv", kTable);
  auto r = ms::test::run_cli("stats confusion '" + f + "' --truth truth --response response --compare-where condition=recorded", dir);
  EXPECT_NE(r.exit_code, 0);
  r = ms::test::run_cli("stats confusion '" + f + "' --truth truth --response response --compare '" + f +
                            "' --compare-where dataset=rec", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("missing column 'dataset'"), std::string::npos) << r.err;
}

}  // namespace
