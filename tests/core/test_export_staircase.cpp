// One staircase definition: the threshold the session stored (staircase.csv's threshold column) and
// `stats staircase` on the exported steps agree, with the protocol's number of reversals.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>

#include "synthesis/tidy_csv.hpp"
#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/export.hpp"
#include "core_fixtures.hpp"
#include "support/test_util.hpp"

using namespace ms;

TEST(ExportStaircase, StatsStaircaseAgreesWithTheStoredThreshold) {
  test::TempDir dir;
  const AutopilotOptions o = ms::testing::shipped_study("demo.yaml", dir);
  ASSERT_TRUE(ms::testing::run_participants_and_export(o, 3, "P", 3, dir.file("out")));
  const TidyCsv t = TidyCsv::read(dir.file("out/staircase.csv"));
  std::map<std::string, double> stored;
  std::map<std::string, std::size_t> steps;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string track = t.cell(r, t.column("participant")) + "/" + t.cell(r, t.column("session")) + "/" +
                              t.cell(r, t.column("block"));
    stored[track] = t.number(r, t.column("threshold"));
    ++steps[track];
    if (r + 1 < t.rows() && t.cell(r + 1, t.column("participant")) == t.cell(r, t.column("participant")))
      EXPECT_EQ(t.number(r, t.column("next_level")), t.number(r + 1, t.column("level")));  // within a track
  }
  ASSERT_EQ(stored.size(), 3u);
  const auto r = test::run_cli("stats staircase " + dir.file("out/staircase.csv") +
                                   " --level level --track participant --track session --track block --trial step --json",
                               dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["tracks"].size(), 3u);
  for (const auto& track : j["tracks"]) {
    const std::string name = track["track"].get<std::string>();
    ASSERT_TRUE(stored.count(name)) << name;
    EXPECT_DOUBLE_EQ(track["threshold"].get<double>(), stored[name]) << name;
    // The protocol's reversals: 8 (unless the track hit its 80-step limit).
    if (steps[name] < 80) EXPECT_EQ(track["reversal_levels"].size(), 8u) << name;
    EXPECT_EQ(track["used"].get<std::size_t>(), track["reversal_levels"].size() - 2) << name;
  }
  EXPECT_TRUE(j["notices"].empty()) << j["notices"].dump();
}
