// Magnitude estimation (analysis/magnitude_estimation) against the independent numpy computation of
// tests/data/magnitude/make_golden.py on its seeded 8-listener x 78-pair study: modulus and
// geometric-mean normalisation factors, the geometric-mean dissimilarity matrices, and the SMACOF map.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <map>

#include "analysis/stats/magnitude_estimation.hpp"
#include "analysis/stats/mds.hpp"
#include "synthesis/tidy_csv.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/magnitude/";
const MagnitudeColumns kCols{"listener", "first", "second", "rating"};

nlohmann::json golden() {
  std::ifstream in(kDir + "golden.json");
  return nlohmann::json::parse(in);
}

// Our matrix permuted into the golden label order.
Eigen::MatrixXd in_golden_order(const MagnitudeEstimation& m, const nlohmann::json& g, Eigen::MatrixXd values) {
  const auto labels = g["labels"].get<std::vector<std::string>>();
  std::map<std::string, Eigen::Index> ours;
  for (std::size_t i = 0; i < m.labels.size(); ++i) ours[m.labels[i]] = Eigen::Index(i);
  const Eigen::Index n = Eigen::Index(labels.size());
  Eigen::MatrixXd out(n, values.cols() == values.rows() ? n : values.cols());
  for (Eigen::Index i = 0; i < n; ++i) {
    if (values.cols() == values.rows())
      for (Eigen::Index j = 0; j < n; ++j) out(i, j) = values(ours.at(labels[std::size_t(i)]), ours.at(labels[std::size_t(j)]));
    else
      out.row(i) = values.row(ours.at(labels[std::size_t(i)]));
  }
  return out;
}

Eigen::MatrixXd json_matrix(const nlohmann::json& j) {
  Eigen::MatrixXd m(Eigen::Index(j.size()), Eigen::Index(j[0].size()));
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index k = 0; k < m.cols(); ++k) m(i, k) = j[std::size_t(i)][std::size_t(k)].get<double>();
  return m;
}

}  // namespace

TEST(MagnitudeEstimation, ModulusNormalisationMatchesNumpy) {
  const nlohmann::json g = golden();
  MagnitudeOptions o;
  o.modulus = {"real", "m1"};
  const MagnitudeEstimation m = magnitude_estimation(TidyCsv::read(kDir + "ratings.csv"), kCols, o);
  ASSERT_EQ(m.labels.size(), 12u);
  ASSERT_EQ(m.listeners.size(), 8u);
  EXPECT_TRUE(m.modulus);
  for (std::size_t l = 0; l < 8; ++l) {
    EXPECT_EQ(m.listeners[l].subject, g["listeners"][l].get<std::string>());
    EXPECT_EQ(m.listeners[l].ratings, 78u);
    EXPECT_NEAR(m.listeners[l].factor, g["factor_modulus"][l].get<double>(), 1e-12);
    // The modulus pair, normalised, is rated exactly 10 by each listener.
    EXPECT_NEAR(m.listeners[l].modulus_rating * m.listeners[l].factor, 10.0, 1e-12);
  }
  const Eigen::MatrixXd ref = json_matrix(g["dissimilarity_modulus"]);
  const Eigen::MatrixXd ours = in_golden_order(m, g, m.dissimilarity);
  EXPECT_LT((ours - ref).cwiseAbs().maxCoeff(), 1e-12 * ref.maxCoeff());
  EXPECT_NEAR(ours(0, 1), 10.0, 1e-12);  // (real, m1): the modulus pair is 10 after aggregation too
  EXPECT_EQ((m.dissimilarity - m.dissimilarity.transpose()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(m.dissimilarity.diagonal().cwiseAbs().maxCoeff(), 0.0);
  for (double s : m.self_ratings) EXPECT_TRUE(s > 0 && s < 2) << s;  // identical pairs rated low

  // The map: SMACOF from the classical start reaches numpy's Guttman-transform solution.
  SmacofOptions so;
  so.random_starts = 0;
  so.tolerance = 1e-13;
  so.max_iterations = 20000;
  const SmacofResult s = smacof(m.dissimilarity, so);
  const auto& gs = g["smacof_classical_start"];
  EXPECT_NEAR(s.stress1, gs["stress1"].get<double>(), 1e-8);
  EXPECT_NEAR(s.raw_stress, gs["raw_stress"].get<double>(), 1e-8 * gs["raw_stress"].get<double>());
  const Eigen::MatrixXd pts = in_golden_order(m, g, s.points), ref_pts = json_matrix(gs["points"]);
  // Same distances (rotation/reflection-free comparison).
  EXPECT_LT((pairwise_distances(pts) - pairwise_distances(ref_pts)).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(MagnitudeEstimation, GeometricMeanNormalisationMatchesNumpy) {
  const nlohmann::json g = golden();
  const MagnitudeEstimation m = magnitude_estimation(TidyCsv::read(kDir + "ratings.csv"), kCols);
  EXPECT_FALSE(m.modulus);
  EXPECT_NEAR(m.grand_geometric_mean, g["grand_geometric_mean"].get<double>(), 1e-12);
  for (std::size_t l = 0; l < 8; ++l) {
    EXPECT_NEAR(m.listeners[l].factor, g["factor_geometric"][l].get<double>(), 1e-12);
    EXPECT_TRUE(std::isnan(m.listeners[l].modulus_rating));
    // Every listener's normalised ratings have the grand geometric mean.
    EXPECT_NEAR(m.listeners[l].geometric_mean * m.listeners[l].factor, m.grand_geometric_mean, 1e-12);
  }
  const Eigen::MatrixXd ref = json_matrix(g["dissimilarity_geometric"]);
  EXPECT_LT((in_golden_order(m, g, m.dissimilarity) - ref).cwiseAbs().maxCoeff(), 1e-12 * ref.maxCoeff());
}

// Hand-computed: two listeners, three tokens; B rates everything twice as high as A.
TEST(MagnitudeEstimation, SmallExampleByHand) {
  const TidyCsv t = TidyCsv::parse(
      "s,a,b,r\nA,x,y,10\nA,x,z,5\nA,y,z,2\nB,y,x,20\nB,x,z,10\nB,z,y,4\nB,z,y,16\n", "m.csv");
  MagnitudeOptions o;
  o.modulus = {"y", "x"};
  const MagnitudeEstimation m = magnitude_estimation(t, {"s", "a", "b", "r"}, o);
  ASSERT_EQ(m.labels, (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_DOUBLE_EQ(m.listeners[0].factor, 1.0);
  EXPECT_DOUBLE_EQ(m.listeners[1].factor, 0.5);
  EXPECT_DOUBLE_EQ(m.dissimilarity(0, 1), 10.0);
  EXPECT_DOUBLE_EQ(m.dissimilarity(0, 2), 5.0);
  // (y, z): A 2; B geometric mean of 4 and 16 = 8, halved = 4; across listeners sqrt(2 * 4).
  EXPECT_NEAR(m.dissimilarity(1, 2), std::sqrt(8.0), 1e-12);
  EXPECT_TRUE(std::isnan(m.self_ratings[0]));
}

TEST(MagnitudeEstimation, BadInputNamesTheCell) {
  auto error = [](const std::string& csv, const MagnitudeOptions& o = {}) {
    try {
      magnitude_estimation(TidyCsv::parse(csv, "m.csv"), {"s", "a", "b", "r"}, o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("s,a,b,r\nA,x,y,1\nA,x,z,0\nA,y,z,2\n"),
            "m.csv:3:7: column 'r': magnitude estimates must be positive (got 0); they are ratios to the modulus");
  EXPECT_EQ(error("s,a,b,r\nA,x,y,1\nA,x,z,-2\nA,y,z,2\n").substr(0, 10), "m.csv:3:7:");
  EXPECT_EQ(error("s,a,b,r\nA,x,y,1\nA,x,z,3\nA,z,z,2\nA,w,x,1\n"),
            "m.csv:1:1: the pair (y, z) was never rated; every pair of tokens is needed");
  MagnitudeOptions o;
  o.modulus = {"x", "y"};
  EXPECT_EQ(error("s,a,b,r\nA,x,y,1\nA,x,z,3\nA,y,z,2\nB,x,z,3\nB,y,z,2\n", o),
            "m.csv:1:1: listener 'B' never rated the modulus pair (x, y)");
  o.modulus = {"x", "q"};
  EXPECT_EQ(error("s,a,b,r\nA,x,y,1\nA,x,z,3\nA,y,z,2\n", o),
            "m.csv:1:1: modulus token 'q' does not occur in columns 'a' / 'b'");
  EXPECT_THROW(magnitude_estimation(TidyCsv::parse("s,a,b,r\nA,x,y,1\n", "m.csv"), {"s", "a", "b", "rating"}),
               InputError);
}
