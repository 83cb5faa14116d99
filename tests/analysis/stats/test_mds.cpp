// MDS against R (tests/data/mds/make_golden.R): classical scaling vs stats::cmdscale, metric SMACOF vs
// a base-R Guttman-transform implementation; exact recovery of Euclidean configurations.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include <nlohmann/json.hpp>

#include "analysis/stats/dissimilarity_matrix.hpp"
#include "analysis/stats/mds.hpp"
#include "synthesis/tidy_csv.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/mds/";

Eigen::MatrixXd read_points(const std::string& file) {
  const TidyCsv t = TidyCsv::read(kDir + file);
  Eigen::MatrixXd p(Eigen::Index(t.rows()), 2);
  for (std::size_t r = 0; r < t.rows(); ++r) {
    p(Eigen::Index(r), 0) = t.number(r, 1);
    p(Eigen::Index(r), 1) = t.number(r, 2);
  }
  return p;
}

// Columns of a configuration are defined up to sign: align each with the reference.
Eigen::MatrixXd align_signs(Eigen::MatrixXd x, const Eigen::MatrixXd& ref) {
  for (Eigen::Index k = 0; k < x.cols(); ++k)
    if (x.col(k).dot(ref.col(k)) < 0) x.col(k) *= -1;
  return x;
}

}  // namespace

TEST(Mds, ClassicalMatchesCmdscale) {
  const DissimilarityMatrix d = dissimilarity_from_square(TidyCsv::read(kDir + "dissimilarity.csv"));
  ASSERT_EQ(d.labels.size(), 10u);
  const ClassicalMds c = classical_mds(d.values, 2);
  const TidyCsv eig = TidyCsv::read(kDir + "classical_eigen_golden.csv");
  ASSERT_EQ(eig.rows(), 10u);
  for (std::size_t k = 0; k < 10; ++k)
    EXPECT_NEAR(c.eigenvalues(Eigen::Index(k)), eig.number(k, 0), 1e-9 * std::abs(eig.number(0, 0))) << k;
  const Eigen::MatrixXd ref = read_points("classical_points_golden.csv");
  EXPECT_LT((align_signs(c.points, ref) - ref).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Mds, SmacofMatchesBaseRImplementation) {
  const DissimilarityMatrix d = dissimilarity_from_square(TidyCsv::read(kDir + "dissimilarity.csv"));
  const TidyCsv golden = TidyCsv::read(kDir + "smacof_stress_golden.csv");
  SmacofOptions o;
  o.random_starts = 0;  // the classical start only, as the R script
  o.tolerance = 1e-13;
  o.max_iterations = 5000;
  const SmacofResult s = smacof(d.values, o);
  // The stopping test sits at rounding level near the end: allow the last iteration or two to differ.
  EXPECT_NEAR(s.iterations, golden.number(0, golden.column("iterations")), 2);
  EXPECT_NEAR(s.raw_stress, golden.number(0, golden.column("raw_stress")), 1e-9 * golden.number(0, 0));
  EXPECT_NEAR(s.stress1, golden.number(0, golden.column("stress1")), 1e-9 * golden.number(0, 1));
  const Eigen::MatrixXd ref = read_points("smacof_points_golden.csv");
  EXPECT_LT((align_signs(s.points, ref) - ref).cwiseAbs().maxCoeff(), 1e-7);
  // SMACOF improves on its classical start (majorisation never increases stress).
  EXPECT_LT(s.raw_stress, raw_stress(d.values, classical_mds(d.values, 2).points));
  // More starts can only find an equal or lower minimum.
  o.random_starts = 8;
  EXPECT_LE(smacof(d.values, o).raw_stress, s.raw_stress * (1 + 1e-12));
}

// Distances of a random planar configuration are reproduced exactly, up to rotation: stress 0.
TEST(Mds, RecoversEuclideanConfiguration) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0, 1);
  Eigen::MatrixXd x(12, 2);
  for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = g(rng);
  const Eigen::MatrixXd delta = pairwise_distances(x);
  const ClassicalMds c = classical_mds(delta, 2);
  EXPECT_LT((pairwise_distances(c.points) - delta).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_NEAR(c.eigenvalues(2), 0.0, 1e-10);  // rank 2
  SmacofOptions o;
  o.random_starts = 3;
  const SmacofResult s = smacof(delta, o);
  EXPECT_LT(s.stress1, 1e-6);
  EXPECT_LT((pairwise_distances(s.points) - delta).cwiseAbs().maxCoeff(), 1e-5);
  // Stress-1 does not depend on the unit of the dissimilarities.
  EXPECT_NEAR(stress1(3.0 * delta, s.points), s.stress1, 1e-12);
}

TEST(Mds, LongFormAveragesPairs) {
  const TidyCsv t = TidyCsv::parse("a,b,d\nx,y,1\ny,x,3\nx,z,4\ny,z,5\nz,z,0\n", "pairs.csv");
  const DissimilarityMatrix m = dissimilarity_from_pairs(t, "a", "b", "d");
  ASSERT_EQ(m.labels, (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(m.values(0, 1), 2.0);
  EXPECT_EQ(m.values(1, 0), 2.0);
  EXPECT_EQ(m.values(2, 1), 5.0);
  EXPECT_EQ(m.averaged_pairs, 1u);
  EXPECT_THROW(dissimilarity_from_pairs(TidyCsv::parse("a,b,d\nx,y,1\nx,z,2\n", "p.csv"), "a", "b", "d"), InputError);
}

TEST(Mds, MonotoneRegressionClosedForm) {
  // 1 3 2 -> 1 2.5 2.5;  4 3 2 1 -> all 2.5.
  EXPECT_EQ(monotone_regression({1, 3, 2}), (std::vector<double>{1, 2.5, 2.5}));
  EXPECT_EQ(monotone_regression({4, 3, 2, 1}), (std::vector<double>{2.5, 2.5, 2.5, 2.5}));
  EXPECT_EQ(monotone_regression({1, 2, 3}), (std::vector<double>{1, 2, 3}));
}

// Nonmetric scaling fits at least as well as metric, is invariant to monotone transforms of the
// data, and reaches the stress MASS::isoMDS reports for the same data (its value, in percent, is
// stored by make_golden.R).
TEST(Mds, NonmetricAgainstIsoMds) {
  const DissimilarityMatrix d = dissimilarity_from_square(TidyCsv::read(kDir + "dissimilarity.csv"));
  SmacofOptions o;
  o.random_starts = 4;
  o.max_iterations = 5000;
  o.tolerance = 1e-12;
  const SmacofResult nm = smacof_nonmetric(d.values, o);
  const SmacofResult metric = smacof(d.values, o);
  EXPECT_LE(nm.stress1, metric.stress1);
  const TidyCsv iso = TidyCsv::read(kDir + "isomds_golden.csv");
  const double iso_stress1 = iso.number(0, iso.column("stress_percent")) / 100;
  EXPECT_LE(nm.stress1, iso_stress1 * 1.05 + 1e-6) << "isoMDS " << iso_stress1;
  // A monotone transform of the dissimilarities leaves the nonmetric solution's stress unchanged.
  const Eigen::MatrixXd squashed = d.values.array().sqrt().matrix();
  EXPECT_NEAR(smacof_nonmetric(squashed, o).stress1, nm.stress1, 1e-3 * nm.stress1 + 1e-6);
}

// scikit-learn comparison (tests/data/mds/sklearn_compare.py): on a seeded 100 x 100 matrix our
// metric SMACOF with the CLI's defaults (classical start + 3 random starts: as many as
// sklearn's n_init = 4) reaches a stress-1 no worse than sklearn.manifold.MDS's best start.
TEST(MdsVsSklearn, StressNoWorseThanSklearnSmacof) {
  const DissimilarityMatrix d = dissimilarity_from_square(TidyCsv::read(kDir + "sklearn_matrix.csv"));
  ASSERT_EQ(d.labels.size(), 100u);
  std::ifstream in(kDir + "sklearn_golden.json");
  const nlohmann::json g = nlohmann::json::parse(in);
  const double sk = g["stress1"].get<double>();
  EXPECT_NEAR(sk, 0.0616064, 1e-6);  // what sklearn 1.2.1 reported when the golden was made
  const SmacofOptions o;              // defaults, as `stats mds --method smacof`
  ASSERT_GE(o.random_starts + 1, g["n_init"].get<int>());
  const SmacofResult s = smacof(d.values, o);
  EXPECT_LE(s.stress1, sk + 1e-6) << "sklearn " << sk;
  EXPECT_NEAR(s.stress1, stress1(d.values, s.points), 1e-14);
  // Each start on its own, too: the classical start alone already matches sklearn's best of 4.
  SmacofOptions one = o;
  one.random_starts = 0;
  EXPECT_LE(smacof(d.values, one).stress1, sk + 1e-6);
}
