// The error against a reference dataset (Sterling 2019 Fig. 1.15): per subject and dataset the mean
// absolute rating difference to the reference over the matched sounds, computed here by hand, and the
// one-way repeated-measures ANOVA on it (two datasets: F is the squared paired t of their errors).
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/stats/reference_error.hpp"
#include "analysis/stats/rm_anova.hpp"

namespace {

using ms::InputError;
using ms::TidyCsv;

const ms::ReferenceErrorColumns kColumns{"value", "participant", "dataset", "rec", {"shape", "material"}};

// Three listeners, two sounds (disc wood, rod metal), the reference "rec" and datasets a and b; p1
// rated a's disc twice (3 and 5: mean 4).
const char* kTable =
    "participant,dataset,shape,material,value\n"
    "p1,rec,disc,wood,3\n" "p1,rec,rod,metal,6\n" "p1,a,disc,wood,3\n" "p1,a,disc,wood,5\n" "p1,a,rod,metal,5\n"
    "p1,b,disc,wood,1\n" "p1,b,rod,metal,7\n"
    "p2,rec,disc,wood,4\n" "p2,rec,rod,metal,4\n" "p2,a,disc,wood,4\n" "p2,a,rod,metal,6\n" "p2,b,disc,wood,7\n"
    "p2,b,rod,metal,1\n"
    "p3,rec,disc,wood,2\n" "p3,rec,rod,metal,5\n" "p3,a,disc,wood,2\n" "p3,a,rod,metal,5\n" "p3,b,disc,wood,4\n"
    "p3,b,rod,metal,6\n";

TEST(ReferenceError, MeanAbsoluteDifferenceToTheReferencePerSubjectAndDataset) {
  const ms::RmData d = ms::reference_error_design(TidyCsv::parse(kTable, "r.csv"), kColumns);
  ASSERT_EQ(d.within.size(), 1u);
  EXPECT_EQ(d.within[0].name, "dataset");
  EXPECT_EQ(d.within[0].levels, (std::vector<std::string>{"a", "b"}));  // the reference is not a level
  EXPECT_EQ(d.subjects, (std::vector<std::string>{"p1", "p2", "p3"}));
  // p1: a |4-3|, |5-6| -> 1; b |1-3|, |7-6| -> 1.5.  p2: a 0, 2 -> 1; b 3, 3 -> 3.  p3: a 0, 0 -> 0; b 2, 1 -> 1.5.
  const double expected[3][2] = {{1.0, 1.5}, {1.0, 3.0}, {0.0, 1.5}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) EXPECT_DOUBLE_EQ(d.cell_mean(i, j), expected[i][j]) << i << "," << j;

  // Two levels: F(1, n-1) is the squared paired t of the differences b - a = 0.5, 2, 1.5.
  const ms::RmAnova a = ms::rm_anova(d);
  const double diff[3] = {0.5, 2.0, 1.5}, mean = 4.0 / 3.0;
  double ss = 0.0;
  for (double x : diff) ss += (x - mean) * (x - mean);
  const double t = mean / std::sqrt(ss / 2.0 / 3.0);
  ASSERT_EQ(a.effects.size(), 1u);
  EXPECT_DOUBLE_EQ(a.effects[0].df1, 1.0);
  EXPECT_DOUBLE_EQ(a.effects[0].df2, 2.0);
  EXPECT_NEAR(a.effects[0].F, t * t, 1e-9 * t * t);
}

void expect_problem(const std::string& table, const std::string& problem, const std::string& where = "") {
  try {
    ms::reference_error_design(TidyCsv::parse(table, "r.csv"), kColumns);
    FAIL() << "accepted: " << table;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what();
    if (!where.empty()) EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
  }
}

TEST(ReferenceError, LocatedProblems) {
  const std::string head = "participant,dataset,shape,material,value\n";
  expect_problem(head + "p1,a,disc,wood,1\np1,b,disc,wood,2\np2,a,disc,wood,1\np2,b,disc,wood,2\n",
                 "no row of the reference dataset 'rec'");
  expect_problem(head + "p1,rec,disc,wood,1\np1,a,disc,wood,2\np2,rec,disc,wood,1\np2,a,disc,wood,2\n",
                 "at least two datasets beside the reference");
  expect_problem(head + "p1,rec,disc,wood,1\np1,a,disc,wood,2\np1,b,disc,wood,2\n", "at least two subjects");
  // p2 rated the rod in a but not in the reference: the row is named.
  expect_problem(head + "p1,rec,disc,wood,1\np1,a,disc,wood,2\np1,b,disc,wood,2\n"
                        "p2,rec,disc,wood,1\np2,a,disc,wood,2\np2,b,disc,wood,2\np2,a,rod,wood,2\n",
                 "rated this sound in 'a' but not in the reference 'rec'", "r.csv:8:");
  expect_problem(head + "p1,rec,disc,wood,1\np1,a,disc,wood,2\np1,b,disc,wood,2\n"
                        "p2,rec,disc,wood,1\np2,a,disc,wood,2\n",
                 "rated this sound in 'rec' but not in 'b'", "r.csv:5:");
  expect_problem(head + "p1,rec,disc,wood,x\n", "r.csv:2:");  // not a number
  try {
    ms::ReferenceErrorColumns c = kColumns;
    c.match = {"size"};
    ms::reference_error_design(TidyCsv::parse(kTable, "r.csv"), c);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("size"), std::string::npos) << e.what();
  }
}

}  // namespace
