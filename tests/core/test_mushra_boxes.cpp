// mushra_boxes: the boxes hold only the assessors post-screening keeps, and the means are theirs.
#include <gtest/gtest.h>

#include <cmath>

#include "studyapp/core/mushra_boxes.hpp"

TEST(MushraBoxes, ExcludedAssessorsAreLeftOutOfBoxesAndMeans) {
  std::vector<ms::MushraRating> r;
  for (int item = 0; item < 4; ++item) {
    const std::string i = std::to_string(item);
    r.push_back({"good1", i, "full", 100});
    r.push_back({"good1", i, "full~lp3500", 20});
    r.push_back({"good2", i, "full", 95});
    r.push_back({"good2", i, "full~lp3500", 30});
    r.push_back({"careless", i, "full", 40});  // the hidden reference below 90 in every item: excluded
    r.push_back({"careless", i, "full~lp3500", 90});
  }
  ms::MushraOptions o;
  o.reference = ms::reference_from_anchor_names({"full~lp3500", "full"});
  ASSERT_EQ(o.reference, "full");
  const ms::MushraBoxes b = ms::mushra_boxes(r, o);
  EXPECT_EQ(b.assessors, 3u);
  EXPECT_EQ(b.kept, 2u);
  ASSERT_EQ(b.conditions.size(), 2u);
  EXPECT_EQ(b.conditions[0], "full");
  EXPECT_EQ(b.ratings[0].size(), 8u);  // 2 kept assessors x 4 items
  EXPECT_DOUBLE_EQ(b.means[0], 97.5);
  EXPECT_DOUBLE_EQ(b.means[1], 25.0);
  EXPECT_FALSE(std::isnan(b.ci_low[1]));
}

TEST(MushraBoxes, NoAutomaticAnchorNoReference) {
  EXPECT_EQ(ms::reference_from_anchor_names({"a", "b"}), "");
  EXPECT_EQ(ms::reference_from_anchor_names({"x~lp7000"}), "x");
}
