// Analytic reference objects against published eigenvalues.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "synthesis/reference_objects.hpp"

using namespace ms;

TEST(FreeFreeBar, RootsOfCosCoshEqualsOne) {
  // Blevins, Formulas for natural frequency and mode shape, Table 8-1 (free-free beam).
  const double published[] = {4.73004074, 7.85320462, 10.9956078, 14.1371655, 17.2787597};
  for (int n = 1; n <= 5; ++n) EXPECT_NEAR(free_bar_root(n), published[n - 1], 1e-7) << n;
  EXPECT_NEAR(free_bar_root(20), (20 + 0.5) * std::numbers::pi, 1e-9);
}

TEST(FreeFreeBar, FrequencyRatiosAndScaling) {
  const ObjectModes bar = free_free_bar(0.3, 0.01, {0.0}, 1e30, 4);
  ASSERT_EQ(bar.lambda0.size(), 4u);
  // f_n/f_1 = (beta_n L / beta_1 L)^2: 2.7565, 5.4039, 8.9330
  EXPECT_NEAR(std::sqrt(bar.lambda0[1] / bar.lambda0[0]), 2.7565, 1e-4);
  EXPECT_NEAR(std::sqrt(bar.lambda0[2] / bar.lambda0[0]), 5.4039, 1e-4);
  EXPECT_NEAR(std::sqrt(bar.lambda0[3] / bar.lambda0[0]), 8.9330, 1e-4);
  // Absolute: omega_1 = 4.73^2 / L^2 * sqrt(E/rho * h^2 / 12) with E/rho = 1.
  EXPECT_NEAR(std::sqrt(bar.lambda0[0]), std::pow(4.73004074, 2) / 0.09 * 0.01 / std::sqrt(12.0), 1e-6);
  // Uniform size scaling s: f ~ 1/s.
  const ObjectModes big = free_free_bar(0.6, 0.02, {0.0}, 1e30, 1);
  EXPECT_NEAR(std::sqrt(bar.lambda0[0] / big.lambda0[0]), 2.0, 1e-12);
}

TEST(FreeFreeBar, ModeShapesAreNormalisedAndStable) {
  // Free end: |phi(0)| = 2 for every mode with mean(phi^2) = 1; large beta L must not overflow.
  const ObjectModes bar = free_free_bar(1.0, 0.01, {0.0, 0.5, 1.0}, 1e30, 60);
  ASSERT_EQ(bar.lambda0.size(), 60u);
  for (std::size_t n = 0; n < 60; ++n) {
    EXPECT_NEAR(std::abs(bar.gains[0][n]), 2.0, 1e-6) << n;
    EXPECT_NEAR(std::abs(bar.gains[2][n]), 2.0, 1e-6) << n;
    EXPECT_TRUE(std::isfinite(bar.gains[1][n]));
  }
  // Odd-numbered (antisymmetric) modes have a node at the centre.
  EXPECT_NEAR(bar.gains[1][1], 0.0, 1e-9);
}

TEST(FreeCircularPlate, LeissaFrequencyParameters) {
  // Leissa (1969), Vibration of Plates, Table 2.3 (free circular plate, nu = 0.33): k^2 =
  // 5.253 (2 diameters, 0 circles), 9.068 (0, 1), 12.23 (3, 0), 20.52 (1, 1).
  const double nu = 0.33;
  EXPECT_NEAR(std::pow(free_plate_roots(2, nu, 10).at(0), 2), 5.253, 0.01);
  EXPECT_NEAR(std::pow(free_plate_roots(0, nu, 10).at(0), 2), 9.068, 0.01);
  EXPECT_NEAR(std::pow(free_plate_roots(3, nu, 10).at(0), 2), 12.23, 0.02);
  EXPECT_NEAR(std::pow(free_plate_roots(1, nu, 10).at(0), 2), 20.52, 0.03);
}

TEST(FreeCircularPlate, ModesSortedWithOrders) {
  const ObjectModes plate = free_circular_plate(0.1, 0.003, 0.33, {0.0, 0.5}, 1e11, 30);
  ASSERT_EQ(plate.lambda0.size(), 30u);
  for (std::size_t i = 1; i < plate.lambda0.size(); ++i) EXPECT_LE(plate.lambda0[i - 1], plate.lambda0[i]);
  EXPECT_EQ(plate.circumferential_order[0], 2);  // the fundamental has two nodal diameters
  // At the centre only axisymmetric (n = 0) modes move.
  for (std::size_t i = 0; i < plate.lambda0.size(); ++i)
    if (plate.circumferential_order[i] != 0) EXPECT_NEAR(plate.gains[0][i], 0.0, 1e-12);
}
