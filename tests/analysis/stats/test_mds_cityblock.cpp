// City-block MDS: exact city-block distances of a random planar configuration are fitted closely (the
// L1 stress surface has many local minima, so near-zero rather than zero), and far better than a
// Euclidean map fits them.
#include <gtest/gtest.h>

#include <random>

#include "analysis/stats/mds_cityblock.hpp"

using namespace ms;

TEST(MdsCityblock, RecoversExactCityblockConfigurations) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::MatrixXd truth(12, 2);
    for (Eigen::Index i = 0; i < truth.size(); ++i) truth.data()[i] = u(rng);
    const Eigen::MatrixXd delta = pairwise_cityblock(truth);
    SmacofOptions o;
    o.dims = 2;
    o.max_iterations = 2000;
    o.tolerance = 1e-12;
    const SmacofResult r = smacof_cityblock(delta, o);
    EXPECT_LT(r.stress1, 0.05) << "seed " << seed;
    // The Euclidean map of the same matrix fits its city-block distances at least twice worse.
    EXPECT_LT(2 * r.stress1, stress1_cityblock(delta, smacof(delta, o).points)) << "seed " << seed;
  }
}

TEST(MdsCityblock, StressOneOfTheTruthIsZero) {
  Eigen::MatrixXd x(4, 2);
  x << 0, 0, 1, 0, 0, 2, 3, 1;
  const Eigen::MatrixXd d = pairwise_cityblock(x);
  EXPECT_DOUBLE_EQ(d(0, 3), 4.0);
  EXPECT_NEAR(stress1_cityblock(d, x), 0.0, 1e-12);
}
