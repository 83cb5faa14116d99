// Descending method of limits, as in the 2002 study's Experiment 1 (a_v from 20 dB down in 1 dB steps).
#include <gtest/gtest.h>

#include "analysis/stats/method_of_limits.hpp"

using namespace ms;

TEST(MethodOfLimits, ThresholdIsTheLastLevelWithoutAChange) {
  // 20, 19, ... : the listener first hears the pruned sound differ at 15 dB -> a_v = 16 dB.
  std::vector<double> levels;
  for (int a = 20; a >= 10; --a) levels.push_back(a);
  std::vector<bool> different(levels.size(), false);
  for (std::size_t i = 5; i < different.size(); ++i) different[i] = true;
  const LimitsThreshold t = descending_limits_threshold(levels, different);
  ASSERT_TRUE(t.threshold.has_value());
  EXPECT_EQ(*t.threshold, 16.0);
  EXPECT_EQ(*t.first_different, 5u);
  EXPECT_FALSE(t.censored);
}

TEST(MethodOfLimits, CensoredAndAboveTheStart) {
  const LimitsThreshold never = descending_limits_threshold({20, 19, 18}, {false, false, false});
  EXPECT_TRUE(never.censored);
  EXPECT_EQ(*never.threshold, 18.0);
  const LimitsThreshold at_once = descending_limits_threshold({20, 19}, {true, true});
  EXPECT_FALSE(at_once.threshold.has_value());
  EXPECT_EQ(*at_once.first_different, 0u);
  EXPECT_THROW(descending_limits_threshold({20, 20}, {false, true}), std::invalid_argument);
  EXPECT_THROW(descending_limits_threshold({20}, {false, true}), std::invalid_argument);
}
