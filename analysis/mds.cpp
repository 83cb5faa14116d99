#include "analysis/mds.hpp"

#include <cmath>
#include <limits>
#include <random>

namespace ms {

Eigen::MatrixXd pairwise_distances(const Eigen::MatrixXd& points) {
  const Eigen::Index n = points.rows();
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j) d(i, j) = d(j, i) = (points.row(i) - points.row(j)).norm();
  return d;
}

double raw_stress(const Eigen::MatrixXd& dissimilarity, const Eigen::MatrixXd& points) {
  const Eigen::MatrixXd d = pairwise_distances(points);
  return 0.5 * (dissimilarity - d).squaredNorm();  // each pair counted twice in the full matrix
}

double stress1(const Eigen::MatrixXd& dissimilarity, const Eigen::MatrixXd& points) {
  const Eigen::MatrixXd d = pairwise_distances(points);
  const double b = (dissimilarity.array() * d.array()).sum() / dissimilarity.squaredNorm();
  return std::sqrt((d - b * dissimilarity).squaredNorm() / d.squaredNorm());
}

ClassicalMds classical_mds(const Eigen::MatrixXd& dissimilarity, int dims) {
  const Eigen::Index n = dissimilarity.rows();
  const Eigen::MatrixXd d2 = dissimilarity.array().square().matrix();
  // Double centring: B = -1/2 J D2 J, written out as row/column/grand means.
  const Eigen::VectorXd row_mean = d2.rowwise().mean();
  const Eigen::RowVectorXd col_mean = d2.colwise().mean();
  const double grand = d2.mean();
  Eigen::MatrixXd b = d2;
  b.colwise() -= row_mean;
  b.rowwise() -= col_mean;
  b.array() += grand;
  b *= -0.5;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(b);
  ClassicalMds out;
  out.eigenvalues = eig.eigenvalues().reverse();  // Eigen sorts ascending
  out.points = Eigen::MatrixXd::Zero(n, dims);
  for (int k = 0; k < dims && k < n; ++k) {
    const double lambda = out.eigenvalues(k);
    if (lambda > 0) out.points.col(k) = eig.eigenvectors().col(n - 1 - k) * std::sqrt(lambda);
  }
  return out;
}

namespace {

// One SMACOF run from `x` (modified in place); returns the final raw stress.
double smacof_run(const Eigen::MatrixXd& delta, Eigen::MatrixXd& x, const SmacofOptions& o, int& iterations) {
  const Eigen::Index n = delta.rows();
  Eigen::MatrixXd bx(n, n);
  double stress = raw_stress(delta, x);
  iterations = 0;
  for (int it = 0; it < o.max_iterations; ++it) {
    const Eigen::MatrixXd d = pairwise_distances(x);
    for (Eigen::Index i = 0; i < n; ++i) {
      double diag = 0;
      for (Eigen::Index j = 0; j < n; ++j) {
        if (i == j) continue;
        bx(i, j) = d(i, j) > 0 ? -delta(i, j) / d(i, j) : 0.0;
        diag -= bx(i, j);
      }
      bx(i, i) = diag;
    }
    x = bx * x / double(n);  // Guttman transform
    const double next = raw_stress(delta, x);
    iterations = it + 1;
    const bool done = stress - next <= o.tolerance * stress;
    stress = next;
    if (done) break;
  }
  return stress;
}

}  // namespace

SmacofResult smacof(const Eigen::MatrixXd& dissimilarity, const SmacofOptions& options) {
  const Eigen::Index n = dissimilarity.rows();
  SmacofResult best;
  best.raw_stress = std::numeric_limits<double>::infinity();
  std::mt19937_64 rng(options.seed);
  // Random starts are spread like the data: uniform in a cube of the dissimilarities' scale.
  const double scale = dissimilarity.maxCoeff();
  std::uniform_real_distribution<double> u(-scale, scale);
  for (int start = 0; start <= options.random_starts; ++start) {
    Eigen::MatrixXd x;
    if (start == 0) {
      x = classical_mds(dissimilarity, options.dims).points;
    } else {
      x.resize(n, options.dims);
      for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = u(rng);
    }
    x.rowwise() -= x.colwise().mean();
    int iterations = 0;
    const double s = smacof_run(dissimilarity, x, options, iterations);
    if (s < best.raw_stress) {
      best.points = x;
      best.raw_stress = s;
      best.iterations = iterations;
      best.best_start = start;
    }
  }
  best.points.rowwise() -= best.points.colwise().mean();
  best.stress1 = stress1(dissimilarity, best.points);
  return best;
}

}  // namespace ms
