// Zheng-James support damping (contact_damping.hpp): the diagonal of G on hand-computed shapes, and on
// the bar and plate sets, where a contact at a node leaves a mode's decay as it was and a contact at
// an antinode adds c w^2 (mu + (1 - mu) cos^2 theta) / 2.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "synthesis/contact_damping.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/reference_objects.hpp"

using namespace ms;

namespace {

ParamSet set(const std::string& text) { return parse_paramset(text, "set.yaml", "."); }

const std::string kBar =
    "duration_s: 0.5\nobject: {type: bar, length_m: 0.3, thickness_m: 0.01}\n"
    "specific_modulus_m2_s2: 2.5e7\ndamping: {law: rayleigh, alpha1: 4, alpha2: 2e-8}\n";
const std::string kPlate =
    "duration_s: 0.5\nobject: {type: plate, radius_m: 0.1, thickness_m: 0.003, poisson: 0.3, max_modes: 40}\n"
    "specific_modulus_m2_s2: 2.5e7\ndamping: {law: rayleigh, alpha1: 4, alpha2: 2e-8}\n";

}  // namespace

TEST(ContactDamping, DiagonalOfGOnGivenShapes) {
  // Shapes w = 2, 0, 1 at one contact of c = 10 1/s, mu = 0.3: G_ii = c w^2 (mu + (1 - mu) cos^2 theta).
  const std::vector<std::vector<double>> shapes = {{2.0, 0.0, 1.0}};
  const auto along = contact_decay_per_s(shapes, {10.0}, {0.0}, 0.3, 3);  // weight 10
  EXPECT_DOUBLE_EQ(along[0], 20.0);
  EXPECT_DOUBLE_EQ(along[1], 0.0);
  EXPECT_DOUBLE_EQ(along[2], 5.0);
  const auto across = contact_decay_per_s(shapes, {10.0}, {90.0}, 0.3, 3);  // weight 10 * 0.3
  EXPECT_NEAR(across[0], 6.0, 1e-12);
  EXPECT_NEAR(across[2], 1.5, 1e-12);
  const auto leaning = contact_decay_per_s(shapes, {10.0}, {45.0}, 0.3, 3);  // 10 (0.3 + 0.7 / 2) = 6.5
  EXPECT_NEAR(leaning[0], 13.0, 1e-12);
  // Contacts add: a second contact of c = 2 with w = 1, 1, 1.
  const auto two = contact_decay_per_s({{2.0, 0.0, 1.0}, {1.0, 1.0, 1.0}}, {10.0, 2.0}, {0.0, 0.0}, 0.3, 3);
  EXPECT_DOUBLE_EQ(two[1], 1.0);
  EXPECT_DOUBLE_EQ(two[2], 6.0);
}

TEST(ContactDamping, BarEndIsAnAntinodeOfEveryModeAndTheCentreANodeOfTheOddOnes) {
  const ParamSet free = set(kBar);
  // At a free end every mass-normalised shape is |w| = 2 (cos 0 + cosh 0): each mode gains c 4 / 2.
  const ParamSet end = set(kBar + "effects: {support_damping: {contacts: [0], mu: 0.3, c: 10}}\n");
  // mu weighs a contact whose normal is across the motion: 10 * 0.3 * 4 / 2 = 6.
  const ParamSet rim = set(kBar + "effects: {support_damping: {contacts: [{position: 1, normal_deg: 90}], mu: 0.3, c: 10}}\n");
  // The centre is a node of the antisymmetric modes (2nd, 4th, ...): those keep their decay.
  const ParamSet centre = set(kBar + "effects: {support_damping: {contacts: [0.5], mu: 0.3, c: 10}}\n");
  ASSERT_GE(free.model.modes.size(), 6u);
  ASSERT_EQ(end.model.modes.size(), free.model.modes.size());
  for (std::size_t i = 0; i < free.model.modes.size(); ++i) {
    const double d = free.model.modes[i].decay_per_s;
    EXPECT_NEAR(end.model.modes[i].decay_per_s - d, 20.0, 1e-6) << i;
    EXPECT_NEAR(rim.model.modes[i].decay_per_s - d, 6.0, 1e-6) << i;
    EXPECT_EQ(end.model.modes[i].freq_hz, free.model.modes[i].freq_hz) << i;
    if (i % 2 == 1) EXPECT_NEAR(centre.model.modes[i].decay_per_s, d, 1e-9) << i;
    else EXPECT_GT(centre.model.modes[i].decay_per_s - d, 1.0) << i;
  }
  // A support under a face (normal along the motion) adds c w^2 / 2 whatever mu is.
  const ParamSet other_mu = set(kBar + "effects: {support_damping: {contacts: [0], mu: 0.9, c: 10}}\n");
  EXPECT_EQ(other_mu.model.modes[3].decay_per_s, end.model.modes[3].decay_per_s);
  EXPECT_NE(end.recipe_hash, free.recipe_hash);
}

TEST(ContactDamping, PlateCentreDampsOnlyTheAxisymmetricModes) {
  const ParamSet free = set(kPlate);
  const ParamSet held = set(kPlate + "effects: {support_damping: {contacts: [{position: 0, c: 8}], mu: 0.5}}\n");
  // The object's own shapes at r = 0, in the set's order (no mode is overdamped or above Nyquist here).
  const ObjectModes plate = free_circular_plate(0.1, 0.003, 0.3, {0.0}, 1e300, 40);
  ASSERT_EQ(free.model.modes.size(), plate.lambda0.size());
  int axisymmetric = 0;
  for (std::size_t i = 0; i < plate.lambda0.size(); ++i) {
    const double added = held.model.modes[i].decay_per_s - free.model.modes[i].decay_per_s;
    const double w = plate.gains[0][i];
    if (plate.circumferential_order[i] > 0) {
      EXPECT_NEAR(added, 0.0, 1e-9) << i;  // J_n(0) = I_n(0) = 0 for n >= 1
    } else {
      ++axisymmetric;
      EXPECT_GT(std::abs(w), 0.5) << i;
      EXPECT_NEAR(added, 0.5 * 8.0 * w * w, 1e-9 * (1.0 + added)) << i;
    }
  }
  EXPECT_GE(axisymmetric, 3);
}
