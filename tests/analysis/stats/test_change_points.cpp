// Fig. 5.4 of Skandalou & Ireland 2017 from change-point marks, counted by hand on a small table: marks
// per value and group, the sweeps heard (a sweep without marks counts), the values marked most often
// with ties at the cut kept, and the located refusals.
#include <gtest/gtest.h>

#include "analysis/stats/change_points.hpp"

namespace {

using ms::ChangepointColumns;
using ms::InputError;
using ms::TidyCsv;

// Two objects, sweeps of Q 1000, 1600, 2200, 3000. jug: p1 marks 1600 and 3000, p2 marks 1600, p3 marks
// nothing. pot: p1 marks 2200, p2 marks 3000.
std::string table() {
  std::string t = "participant,block,trial,object,value,marked\n";
  const auto sweep = [&](const std::string& who, const std::string& trial, const std::string& object,
                         const std::vector<int>& marked) {
    const int values[] = {1000, 1600, 2200, 3000};
    for (int i = 0; i < 4; ++i)
      t += who + ",q," + trial + "," + object + "," + std::to_string(values[i]) + "," + std::to_string(marked[i]) + "\n";
  };
  sweep("p1", "0", "jug", {0, 1, 0, 1});
  sweep("p1", "1", "pot", {0, 0, 1, 0});
  sweep("p2", "0", "pot", {0, 0, 0, 1});
  sweep("p2", "1", "jug", {0, 1, 0, 0});
  sweep("p3", "0", "jug", {0, 0, 0, 0});
  return t;
}

TEST(ChangePoints, MarksPerValueAndGroupByHand) {
  ChangepointColumns c;
  c.by = {"object"};
  const auto groups = ms::change_points_from_table(TidyCsv::parse(table(), "c.csv"), c, 1);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].name, "jug");
  EXPECT_EQ(groups[0].sweeps, 3u);  // p3's sweep without marks is heard too
  EXPECT_EQ(groups[0].values, (std::vector<double>{1000, 1600, 2200, 3000}));
  EXPECT_EQ(groups[0].marks, (std::vector<std::size_t>{0, 2, 0, 1}));
  EXPECT_EQ(groups[0].most_chosen, (std::vector<double>{1600}));
  EXPECT_EQ(groups[1].name, "pot");
  EXPECT_EQ(groups[1].sweeps, 2u);
  EXPECT_EQ(groups[1].marks, (std::vector<std::size_t>{0, 0, 1, 1}));
  EXPECT_EQ(groups[1].most_chosen, (std::vector<double>{2200, 3000}));  // a tie at the cut is kept
}

TEST(ChangePoints, AllSweepsTogetherWithoutGroups) {
  const auto groups = ms::change_points_from_table(TidyCsv::parse(table(), "c.csv"), {}, 4);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].sweeps, 5u);
  EXPECT_EQ(groups[0].marks, (std::vector<std::size_t>{0, 2, 1, 2}));
  EXPECT_EQ(groups[0].most_chosen, (std::vector<double>{1600, 3000, 2200}));  // by count, then value; no zeros
}

std::string refusal(const std::string& text) {
  try {
    ms::change_points_from_table(TidyCsv::parse(text, "c.csv"), {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ChangePoints, BadRowsAreRefusedAtTheirCell) {
  const std::string head = "participant,block,trial,value,marked\n";
  std::string e = refusal(head + "p1,q,0,1000,0\np1,q,0,1000,1\n");
  EXPECT_NE(e.find("c.csv:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("plays 1000 twice"), std::string::npos) << e;
  e = refusal(head + "p1,q,0,1000,2\n");
  EXPECT_NE(e.find("c.csv:2:"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 1 (marked) or 0"), std::string::npos) << e;
  e = refusal(head + "p1,q,0,high,0\n");
  EXPECT_NE(e.find("c.csv:2:"), std::string::npos) << e;
  EXPECT_NE(refusal(head).find("no data rows"), std::string::npos);
  EXPECT_NE(refusal("participant,block,trial,marked\np1,q,0,1\n").find("'value'"), std::string::npos);
}

}  // namespace
