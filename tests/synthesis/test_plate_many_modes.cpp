// A free plate asked for thousands of modes: high orders underflow at small k, which must not be taken
// for a sign change (it made Boost's root finder fail with "do not bracket the root").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "synthesis/reference_objects.hpp"

TEST(PlateManyModes, TwentySixHundredModesAscendingAndOnTheirOrder) {
  const ms::ObjectModes m = ms::free_circular_plate(1.0, 1.0, 0.33, {0.3}, 1e300, 2602);
  ASSERT_EQ(m.lambda0.size(), 2602u);
  EXPECT_TRUE(std::is_sorted(m.lambda0.begin(), m.lambda0.end()));
  EXPECT_GT(m.lambda0.front(), 0.0);
  // The highest orders were reached (where J_n and I_n underflow near k = 0.5).
  const int max_order = *std::max_element(m.circumferential_order.begin(), m.circumferential_order.end());
  EXPECT_GT(max_order, 60);
  for (double g : m.gains[0]) EXPECT_TRUE(std::isfinite(g));
}

TEST(PlateManyModes, NoRootWhereTheEquationUnderflows) {
  // Order 150: J_150(k) underflows for small k; the first root lies above k = 150.
  const auto roots = ms::free_plate_roots(150, 0.33, 200.0);
  ASSERT_FALSE(roots.empty());
  EXPECT_GT(roots.front(), 150.0);
}
