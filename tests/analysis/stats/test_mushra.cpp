// MUSHRA post-screening and summaries against base R (tests/data/mushra/make_golden.R), and the
// BS.1534-3 15 % rule at its boundary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/stats/mushra.hpp"
#include "synthesis/tidy_csv.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/mushra/";

std::vector<MushraRating> read_ratings() {
  const TidyCsv t = TidyCsv::read(kDir + "results.csv");
  std::vector<MushraRating> out;
  for (std::size_t r = 0; r < t.rows(); ++r)
    out.push_back({t.cell(r, t.column("participant")), t.cell(r, t.column("trial")), t.cell(r, t.column("condition")),
                   t.number(r, t.column("rating"))});
  return out;
}

void expect_rel(double actual, double expected, const std::string& what) {
  EXPECT_NEAR(actual, expected, 1e-9 * std::abs(expected) + 1e-12) << what;
}

}  // namespace

TEST(Mushra, ScreeningAndSummariesMatchR) {
  MushraOptions opt;
  opt.anchors = {"anchor70", "anchor35"};
  const MushraResult res = mushra_analyse(read_ratings(), opt);
  const TidyCsv screen = TidyCsv::read(kDir + "screening_golden.csv");
  ASSERT_EQ(res.assessors.size(), screen.rows());
  std::size_t kept = 0;
  for (std::size_t r = 0; r < screen.rows(); ++r) {
    const std::string subject = screen.cell(r, 0);
    const auto it = std::find_if(res.assessors.begin(), res.assessors.end(),
                                 [&](const MushraAssessor& a) { return a.subject == subject; });
    ASSERT_NE(it, res.assessors.end()) << subject;
    EXPECT_EQ(it->reference_items, 8u);
    expect_rel(double(it->reference_below) / double(it->reference_items),
               screen.number(r, screen.column("reference_fraction")), subject);
    EXPECT_EQ(it->excluded, screen.cell(r, screen.column("excluded")) == "TRUE") << subject;
    expect_rel(double(it->anchors[0].above) / double(it->anchors[0].items),
               screen.number(r, screen.column("anchor70_fraction")), subject + " anchor70");
    expect_rel(double(it->anchors[1].above) / double(it->anchors[1].items),
               screen.number(r, screen.column("anchor35_fraction")), subject + " anchor35");
    EXPECT_EQ(it->anchor_fails, screen.cell(r, screen.column("anchor_fails")) == "TRUE") << subject;
    kept += !it->excluded;
  }
  EXPECT_EQ(res.included, kept);
  EXPECT_EQ(res.averaged, 6u);  // P05 rated item3 twice, 6 conditions

  const TidyCsv golden = TidyCsv::read(kDir + "summary_golden.csv");
  std::size_t checked = 0;
  for (std::size_t r = 0; r < golden.rows(); ++r) {
    const std::string item = golden.cell(r, 0), cond = golden.cell(r, 1);
    const std::vector<MushraStat>* stats = &res.conditions;
    if (item != "ALL") {
      const auto it = std::find_if(res.items.begin(), res.items.end(), [&](const MushraItem& i) { return i.item == item; });
      ASSERT_NE(it, res.items.end());
      stats = &it->conditions;
    }
    const auto s = std::find_if(stats->begin(), stats->end(), [&](const MushraStat& m) { return m.condition == cond; });
    ASSERT_NE(s, stats->end());
    const std::string tag = item + " " + cond;
    EXPECT_EQ(double(s->n), golden.number(r, golden.column("n"))) << tag;
    expect_rel(s->mean, golden.number(r, golden.column("mean")), tag + " mean");
    expect_rel(s->sd, golden.number(r, golden.column("sd")), tag + " sd");
    expect_rel(*s->ci_low, golden.number(r, golden.column("ci_low")), tag + " ci_low");
    expect_rel(*s->ci_high, golden.number(r, golden.column("ci_high")), tag + " ci_high");
    ++checked;
  }
  EXPECT_EQ(checked, 6u * 9u);
}

// 15 % of items: with 20 items, 3 misses (15 %) keep the assessor, 4 (20 %) exclude.
TEST(Mushra, FifteenPercentBoundary) {
  std::vector<MushraRating> ratings;
  for (int misses : {3, 4})
    for (int i = 0; i < 20; ++i) {
      const std::string who = "miss" + std::to_string(misses);
      ratings.push_back({who, "i" + std::to_string(i), "reference", i < misses ? 89.0 : 90.0});
      ratings.push_back({who, "i" + std::to_string(i), "codec", 50.0 + i});
    }
  const MushraResult res = mushra_analyse(ratings, MushraOptions{});
  ASSERT_EQ(res.assessors.size(), 2u);
  EXPECT_FALSE(res.assessors[0].excluded);  // a rating of exactly 90 is not below 90
  EXPECT_TRUE(res.assessors[1].excluded);
  EXPECT_EQ(res.included, 1u);
  // Mean of 50..69 over the kept assessor; t interval closed form: sd of 0..19 = sqrt(35).
  const MushraStat& codec = res.conditions[1];
  EXPECT_DOUBLE_EQ(codec.mean, 59.5);
  EXPECT_NEAR(codec.sd, std::sqrt(35.0), 1e-12);
  EXPECT_NEAR(*codec.ci_high - codec.mean, 2.0930240544083096 * std::sqrt(35.0 / 20.0), 1e-9);  // t_{19,0.975}
}
