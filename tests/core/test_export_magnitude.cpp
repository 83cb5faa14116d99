// The modulus of magnitude estimation is one number, from the protocol: the session's listener, the
// export's modulus columns and `stats magnitude` all use it.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

#include "synthesis/tidy_csv.hpp"
#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "core_fixtures.hpp"
#include "support/test_util.hpp"

using namespace ms;

TEST(ExportMagnitude, ModulusFromTheProtocolInExportAndStats) {
  test::TempDir dir;
  const AutopilotOptions o = ms::testing::shipped_study("demo.yaml", dir);
  ASSERT_TRUE(ms::testing::run_participants_and_export(o, 2, "P", 7, dir.file("out")));
  const TidyCsv t = TidyCsv::read(dir.file("out/magnitude.csv"));
  ASSERT_GT(t.rows(), 0u);
  for (std::size_t r = 0; r < t.rows(); ++r) {
    EXPECT_EQ(t.cell(r, t.column("modulus_a")), "metal");
    EXPECT_EQ(t.cell(r, t.column("modulus_b")), "glass");
    EXPECT_EQ(t.number(r, t.column("modulus_value")), 100.0);  // the protocol's default
  }
  // stats magnitude reads the pair and the value from those columns: the modulus pair is 100.
  const std::string args = "stats magnitude " + dir.file("out/magnitude.csv") +
                           " --subject participant --a first --b second --rating value --dims 1 --json";
  const auto r = test::run_cli(args, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["normalisation"], "modulus");
  EXPECT_EQ(j["modulus"], nlohmann::json({"metal", "glass"}));
  EXPECT_EQ(j["modulus_value"], 100.0);
  const auto labels = j["labels"].get<std::vector<std::string>>();
  const auto at = [&](const std::string& s) { return std::size_t(std::find(labels.begin(), labels.end(), s) - labels.begin()); };
  EXPECT_NEAR(j["dissimilarity"][at("metal")][at("glass")].get<double>(), 100.0, 1e-9);
  // An explicit --modulus-value wins (the literature's 10).
  const auto ten = nlohmann::json::parse(test::run_cli(args + " --modulus-value 10", dir).out);
  EXPECT_NEAR(ten["dissimilarity"][at("metal")][at("glass")].get<double>(), 10.0, 1e-9);
}

TEST(ExportMagnitude, VanDenDoelTellsAndUsesTheSameModulus) {
  const Protocol p = load_protocol(std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/vandendoel2002.yaml");
  std::size_t blocks = 0;
  for (const Block& b : p.blocks) {
    if (const auto* i = std::get_if<InstructionsBlock>(&b.body); i && b.id == "exp3")
      EXPECT_NE(i->text.find("dissimilarity is 10."), std::string::npos) << i->text;
    if (const auto* m = std::get_if<MagnitudeBlock>(&b.body)) {
      EXPECT_EQ(m->modulus_value, 10.0) << b.id;  // the paper's anchor, at the top of its 1-10 scale
      ASSERT_TRUE(m->scale.has_value()) << b.id;
      EXPECT_EQ(m->scale->min, 1.0) << b.id;  // 1 = identical
      EXPECT_EQ(m->scale->max, 10.0) << b.id;
      ++blocks;
    }
  }
  EXPECT_EQ(blocks, 4u);
}
