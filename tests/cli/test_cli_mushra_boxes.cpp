// stats mushra --plot draws ms::mushra_boxes, the experimenter view's recipe: the means and intervals
// the CLI reports and the kept-assessor count in its picture's title equal mushra_boxes over the table.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "analysis/stats/mushra.hpp"
#include "studyapp/core/mushra_boxes.hpp"
#include "support/test_util.hpp"

TEST(CliMushraBoxes, PictureAndReportAreMushraBoxes) {
  const std::string data = std::string(MODALSTUDY_TEST_DATA) + "/mushra/results.csv";
  ms::test::TempDir dir;
  const std::string svg = dir.file("boxes.svg");
  const auto r = ms::test::run_cli("stats mushra " + data + " --anchor anchor70 --screen-anchors --json --plot " + svg, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ms::MushraOptions o;
  o.anchors = {"anchor70"};
  o.screen_anchors = true;
  const ms::MushraTable t = ms::mushra_from_table(ms::TidyCsv::read(data), {}, o);
  const ms::MushraBoxes boxes = ms::mushra_boxes(t.ratings, t.options);
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["conditions"].size(), boxes.conditions.size());
  for (std::size_t i = 0; i < boxes.conditions.size(); ++i) {
    const auto& c = j["conditions"][i];
    EXPECT_EQ(c["condition"], boxes.conditions[i]);
    EXPECT_NEAR(c["mean"].get<double>(), boxes.means[i], 1e-12);
    if (!c["ci_low"].is_null()) EXPECT_NEAR(c["ci_low"].get<double>(), boxes.ci_low[i], 1e-12);
  }
  EXPECT_EQ(j["n_included"].get<std::size_t>(), boxes.kept);
  std::ifstream in(svg);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_NE(s.str().find("(" + std::to_string(boxes.kept) + " assessors kept)"), std::string::npos);
}
