// adjust.csv names each answer's target and the value the target states for the row's key (`truth:` on the
// target stimulus), so `stats adjust` can give the error against the truth: run the hand-tuning protocol
// (protocols/sterling2019_handtuning.yaml) with the simulated listener and export it. Protocols whose
// targets state nothing export adjust.csv as before (the demo database of ExportStoredAnswers, whose
// adjust block has a target without a truth, keeps its table byte for byte).
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "support/test_util.hpp"
#include "synthesis/tidy_csv.hpp"

namespace {

TEST(ExportAdjustTruth, TheTargetAndItsStatedValueBesideEachChoice) {
  const std::string protocol_path = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/sterling2019_handtuning.yaml";
  const ms::test::TempDir dir;
  ms::AutopilotOptions o;
  o.protocol_path = protocol_path;
  o.participant = "P01";
  o.db_path = dir.file("h.sqlite");
  o.cache_dir = dir.file("cache");
  o.seed = 1;
  ASSERT_TRUE(ms::run_autopilot(o).finished);
  ms::export_results(o.db_path, dir.file("out"));
  const ms::TidyCsv t = ms::TidyCsv::read(dir.file("out/adjust.csv"));
  const std::vector<std::string> expected_tail = {"stimulus", "key", "value", "plays", "rt_ms", "target", "truth", "object", "section"};
  ASSERT_GE(t.header().size(), expected_tail.size());
  EXPECT_EQ(std::vector<std::string>(t.header().end() - long(expected_tail.size()), t.header().end()), expected_tail);

  std::vector<std::string> problems;
  const ms::Protocol p = ms::load_protocol(protocol_path, &problems);
  ASSERT_TRUE(problems.empty());
  std::size_t known = 0, unknown = 0;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string block = t.cell(r, t.column("block")), target = t.cell(r, t.column("target"));
    EXPECT_EQ(std::get<ms::AdjustBlock>(p.find_block(block)->body).target->name, target) << block;
    std::map<std::string, std::string> stated;
    for (const auto& [k, v] : p.find_stimulus(target)->truth) stated[k] = v;
    const std::string& truth = t.cell(r, t.column("truth"));
    if (stated.empty()) {  // the training cymbal: a real recording
      EXPECT_EQ(truth, "NA") << block;
      ++unknown;
    } else {
      EXPECT_EQ(truth, stated.at(t.cell(r, t.column("key")))) << block;
      ++known;
    }
  }
  EXPECT_EQ(known, 6u * 3 + 6u * 2);  // six objects: three sliders, then two
  EXPECT_EQ(unknown, 3u + 2u);        // the two training answers
}

}  // namespace
