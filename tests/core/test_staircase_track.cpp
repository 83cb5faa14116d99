// StaircaseTrack: the 2-down-1-up rule moves, reverses and ends as Levitt's rule says, and its
// threshold equals analysis/staircase's mean of reversal levels (after the first two).
#include <gtest/gtest.h>

#include "analysis/stats/staircase.hpp"
#include "studyapp/core/staircase_track.hpp"

namespace ms {
namespace {

TEST(StaircaseTrack, TwoDownOneUpMovesAndReverses) {
  // step -1 is the easier direction (a_v: lower prunes more): correct pairs raise the level.
  StaircaseTrack t(20.0, -1.0, 2, 1, 4);
  t.record(true);
  EXPECT_EQ(t.level(), 20.0);  // one correct: no move yet
  t.record(true);
  EXPECT_EQ(t.level(), 21.0);  // two correct: harder (-step)
  t.record(false);
  EXPECT_EQ(t.level(), 20.0);  // one wrong: easier (+step), a reversal
  EXPECT_EQ(t.reversals(), 1u);
  t.record(false);
  EXPECT_EQ(t.level(), 19.0);
  EXPECT_EQ(t.reversals(), 1u);
  t.record(true);
  t.record(true);
  EXPECT_EQ(t.level(), 20.0);
  EXPECT_EQ(t.reversals(), 2u);
  EXPECT_FALSE(t.finished());
  t.record(false);  // 3rd reversal
  t.record(true);
  t.record(true);   // 4th
  EXPECT_TRUE(t.finished());
  EXPECT_EQ(t.levels(), (std::vector<double>{20, 20, 21, 20, 19, 19, 20, 19, 19}));
}

TEST(StaircaseTrack, ThresholdMatchesAnalysisStaircase) {
  StaircaseTrack t(10.0, 1.0, 1, 1, 8);  // 1-up-1-down with step +1 = easier
  const bool answers[] = {true, true, true, false, true, false, false, true, false, true, false, true, true, false};
  for (bool a : answers)
    if (!t.finished()) t.record(a);
  // analysis/staircase counts reversals from the presented levels (and the final one), averaging the last k.
  StaircaseOptions all;
  all.last_k = 1000;
  const auto ref = staircase_threshold(t.levels(), t.level(), all);
  EXPECT_EQ(ref.reversal_levels.size(), t.reversals());
  ASSERT_TRUE(ref.threshold.has_value());
  ASSERT_TRUE(t.threshold().has_value());
  std::vector<double> rev = ref.reversal_levels;
  const std::size_t skip = rev.size() > 4 ? 2 : 0;
  double sum = 0;
  for (std::size_t i = skip; i < rev.size(); ++i) sum += rev[i];
  EXPECT_NEAR(*t.threshold(), sum / double(rev.size() - skip), 1e-12);
}

TEST(StaircaseTrack, EndsAfterMaxStepsWithoutReversals) {
  StaircaseTrack t(0.0, 1.0, 2, 1, 8);
  while (!t.finished()) t.record(false);  // never correct: always easier, never reverses
  EXPECT_EQ(t.levels().size(), StaircaseTrack::kMaxSteps);
  EXPECT_FALSE(t.threshold().has_value());
}

}  // namespace
}  // namespace ms
