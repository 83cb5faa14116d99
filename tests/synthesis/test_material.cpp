// The material library holds both published tables exactly, each entry with its source.
#include <gtest/gtest.h>

#include "synthesis/material.hpp"

using namespace ms;

TEST(Material, RenTableValues) {
  struct Row { const char* id; double alpha, beta, gamma, sigma; };
  const Row rows[] = {{"ren2013/wood", 2.1364, 3.0828e-6, 6.6625e5, 3.3276e-6},
                      {"ren2013/plastic", 52.627, 8.7753e-7, 8.9008e4, 2.2050e-6},
                      {"ren2013/metal", 6.3035, 2.1160e-8, 4.5935e5, 9.2624e-6},
                      {"ren2013/glass", 18.301, 1.4342e-7, 2.0282e5, 1.1336e-6},
                      {"ren2013/porcelain", 0.037388, 8.4142e-8, 3.7068e5, 4.3800e-7}};
  for (const Row& r : rows) {
    const Material* m = find_material(r.id);
    ASSERT_NE(m, nullptr) << r.id;
    EXPECT_EQ(m->rayleigh.alpha1, r.alpha);
    EXPECT_EQ(m->rayleigh.alpha2, r.beta);
    EXPECT_EQ(m->specific_modulus_m2_s2, r.gamma);
    EXPECT_EQ(m->amp_scale, r.sigma);
    EXPECT_FALSE(m->hybrid.has_value());
    EXPECT_NE(m->source.find("Ren"), std::string::npos);
  }
}

TEST(Material, SterlingTableValues) {
  struct Row { const char* id; double a1, a2, h1, h2, h3; };
  const Row rows[] = {{"sterling2019/porcelain", 3.9, 1e-8, 3.9, 5.2e-9, 1.027},
                      {"sterling2019/travertine", 1.3, 2.5e-8, 1.3, 2.5e-8, 1.001},
                      {"sterling2019/wood", 39.0, 1.3e-7, 39.0, 2.1e-7, 0.978},
                      {"sterling2019/steel", 2.3, 6.9e-8, 2.4, 5.5e-8, 1.011},
                      {"sterling2019/plastic", 39.8, 1.3e-7, 34.83, 4.1e-7, 0.95},
                      {"sterling2019/glass", 2.0, 7.8e-8, 1.9, 1.5e-7, 0.974}};
  for (const Row& r : rows) {
    const Material* m = find_material(r.id);
    ASSERT_NE(m, nullptr) << r.id;
    EXPECT_EQ(m->rayleigh.alpha1, r.a1);
    EXPECT_EQ(m->rayleigh.alpha2, r.a2);
    ASSERT_TRUE(m->hybrid.has_value());
    EXPECT_EQ(m->hybrid->alpha1, r.h1);
    EXPECT_EQ(m->hybrid->alpha2, r.h2);
    EXPECT_EQ(m->hybrid->alpha3, r.h3);
    EXPECT_EQ(m->hybrid->kind, DampingKind::hybrid);
    EXPECT_NE(m->source.find("Sterling"), std::string::npos);
    EXPECT_GT(m->specific_modulus_m2_s2, 0.0);
    EXPECT_FALSE(m->modulus_source.empty());
  }
  EXPECT_EQ(material_library().size(), 11u);
  EXPECT_EQ(find_material("sterling2019/unobtainium"), nullptr);
}
