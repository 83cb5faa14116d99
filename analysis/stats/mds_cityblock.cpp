#include "analysis/stats/mds_cityblock.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace ms {

Eigen::MatrixXd pairwise_cityblock(const Eigen::MatrixXd& points) {
  const Eigen::Index n = points.rows();
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j) d(i, j) = d(j, i) = (points.row(i) - points.row(j)).cwiseAbs().sum();
  return d;
}

namespace {

double raw_stress_cityblock(const Eigen::MatrixXd& delta, const Eigen::MatrixXd& x) {
  const Eigen::MatrixXd d = pairwise_cityblock(x);
  double s = 0;
  for (Eigen::Index i = 0; i < delta.rows(); ++i)
    for (Eigen::Index j = i + 1; j < delta.rows(); ++j) s += std::pow(delta(i, j) - d(i, j), 2);
  return s;
}

// One start: majorization steps until the raw stress stops falling.
std::pair<Eigen::MatrixXd, int> descend(const Eigen::MatrixXd& delta, Eigen::MatrixXd x, const SmacofOptions& o) {
  const Eigen::Index n = x.rows(), dims = x.cols();
  double scale = delta.cwiseAbs().maxCoeff();
  const double eps = 1e-9 * (scale > 0 ? scale : 1.0);
  double stress = raw_stress_cityblock(delta, x);
  int it = 0;
  Eigen::MatrixXd lap(n, n);
  Eigen::VectorXd b(n);
  for (; it < o.max_iterations; ++it) {
    const Eigen::MatrixXd d = pairwise_cityblock(x);
    Eigen::MatrixXd next(n, dims);
    for (Eigen::Index k = 0; k < dims; ++k) {
      lap.setZero();
      b.setZero();
      for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = i + 1; j < n; ++j) {
          const double diff = x(i, k) - x(j, k);
          const double a = d(i, j) / std::max(std::abs(diff), eps);
          lap(i, j) -= a;
          lap(j, i) -= a;
          lap(i, i) += a;
          lap(j, j) += a;
          const double s = diff > 0 ? 1.0 : (diff < 0 ? -1.0 : 0.0);
          b(i) += delta(i, j) * s;
          b(j) -= delta(i, j) * s;
        }
      // The Laplacian is singular along 1: adding 11' fixes the centred solution (b sums to 0).
      lap.array() += 1.0;
      next.col(k) = lap.ldlt().solve(b);
    }
    const double next_stress = raw_stress_cityblock(delta, next);
    if (!(next_stress < stress)) break;
    const bool small = (stress - next_stress) <= o.tolerance * stress;
    x = next;
    stress = next_stress;
    if (small) break;
  }
  return {x, it};
}

}  // namespace

double stress1_cityblock(const Eigen::MatrixXd& delta, const Eigen::MatrixXd& points) {
  const Eigen::MatrixXd d = pairwise_cityblock(points);
  double dd = 0, dl = 0, ll = 0;
  for (Eigen::Index i = 0; i < delta.rows(); ++i)
    for (Eigen::Index j = i + 1; j < delta.rows(); ++j) {
      dd += d(i, j) * d(i, j);
      dl += d(i, j) * delta(i, j);
      ll += delta(i, j) * delta(i, j);
    }
  if (dd <= 0 || ll <= 0) return 0.0;
  const double b = dl / ll;
  double num = 0;
  for (Eigen::Index i = 0; i < delta.rows(); ++i)
    for (Eigen::Index j = i + 1; j < delta.rows(); ++j) num += std::pow(d(i, j) - b * delta(i, j), 2);
  return std::sqrt(num / dd);
}

SmacofResult smacof_cityblock(const Eigen::MatrixXd& delta, const SmacofOptions& options) {
  const SmacofResult euclid = smacof(delta, options);
  std::vector<Eigen::MatrixXd> starts;
  if (options.dims == 2) {
    for (int deg = 0; deg < 90; deg += 15) {
      const double t = deg * std::numbers::pi / 180.0;
      Eigen::Matrix2d rot;
      rot << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
      starts.push_back(euclid.points * rot);
    }
  } else {
    starts.push_back(euclid.points);
  }
  std::mt19937_64 rng(options.seed);
  std::normal_distribution<double> gauss(0.0, delta.maxCoeff() / 2.0);
  for (int s = 0; s < options.random_starts; ++s) {
    Eigen::MatrixXd x(delta.rows(), options.dims);
    for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = gauss(rng);
    starts.push_back(x);
  }
  SmacofResult best;
  best.raw_stress = INFINITY;
  for (std::size_t s = 0; s < starts.size(); ++s) {
    auto [x, it] = descend(delta, starts[s], options);
    const double r = raw_stress_cityblock(delta, x);
    if (r < best.raw_stress) {
      best.points = x.rowwise() - x.colwise().mean();
      best.raw_stress = r;
      best.iterations = it;
      best.best_start = int(s);
    }
  }
  best.stress1 = stress1_cityblock(delta, best.points);
  return best;
}

}  // namespace ms
