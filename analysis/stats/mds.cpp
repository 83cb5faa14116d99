#include "analysis/stats/mds.hpp"

#include <algorithm>
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

// One SMACOF run from `x` (modified in place); returns the raw stress of the final `x`.
// Each iteration is one pass over the pairs i < j, column j of the upper triangle at a time, as
// Eigen array expressions over i = 0..j-1 (SIMD, including the reductions): the distances d_ij,
// the stress terms (delta_ij - d_ij)^2, and the Guttman transform written without the matrix B,
//   (B(X)X)_i = sum_{j != i} w_ij (x_i - x_j),  w_ij = delta_ij / d_ij (0 when d_ij = 0),
// accumulated into Y for i and, with the opposite sign, for j. Buffers are allocated once; nothing
// is allocated inside the loop; O(n^2 K) per iteration.
// The stress computed in a pass is that of the configuration the pass transforms, so the stopping
// test compares sigma(X_k) with sigma(X_{k-1}) and, when it fires, returns X_k unchanged.
double smacof_run(const Eigen::MatrixXd& delta, Eigen::MatrixXd& x, const SmacofOptions& o, int& iterations) {
  const Eigen::Index n = delta.rows(), k_dims = x.cols();
  Eigen::MatrixXd y(n, k_dims);
  Eigen::ArrayXd dist(n), weight(n), diff(n);
  const double inv_n = 1.0 / double(n);
  double previous = std::numeric_limits<double>::infinity();
  double stress = 0;
  iterations = 0;
  for (int it = 0;; ++it) {
    y.setZero();
    stress = 0;
    for (Eigen::Index j = 1; j < n; ++j) {
      auto d = dist.head(j);
      auto w = weight.head(j);
      auto dk = diff.head(j);
      d = (x.col(0).head(j).array() - x(j, 0)).square();
      for (Eigen::Index k = 1; k < k_dims; ++k) d += (x.col(k).head(j).array() - x(j, k)).square();
      d = d.sqrt();
      const auto del = delta.col(j).head(j).array();
      stress += (del - d).square().sum();
      w = (d > 0).select(del / d, 0.0);
      for (Eigen::Index k = 0; k < k_dims; ++k) {
        dk = w * (x.col(k).head(j).array() - x(j, k));
        y.col(k).head(j).array() += dk;
        y(j, k) -= dk.sum();
      }
    }
    if ((it > 0 && previous - stress <= o.tolerance * previous) || it >= o.max_iterations) break;
    previous = stress;
    iterations = it + 1;
    x.swap(y);
    x *= inv_n;  // Guttman transform X <- (1/n) B(X) X
  }
  return stress;
}

}  // namespace

std::vector<double> monotone_regression(const std::vector<double>& y) {
  // Blocks of (mean, size); merge backwards while the order is violated.
  std::vector<double> mean;
  std::vector<std::size_t> size;
  for (double v : y) {
    mean.push_back(v);
    size.push_back(1);
    while (mean.size() > 1 && mean[mean.size() - 2] > mean.back()) {
      const std::size_t k = mean.size() - 1;
      const double m = (mean[k - 1] * double(size[k - 1]) + mean[k] * double(size[k])) / double(size[k - 1] + size[k]);
      mean[k - 1] = m;
      size[k - 1] += size[k];
      mean.pop_back();
      size.pop_back();
    }
  }
  std::vector<double> fit;
  for (std::size_t b = 0; b < mean.size(); ++b) fit.insert(fit.end(), size[b], mean[b]);
  return fit;
}

namespace {

struct PairOrder {
  std::vector<std::pair<Eigen::Index, Eigen::Index>> pairs;  // (i < j) sorted by delta
  std::vector<std::size_t> tie_block_end;                    // one past the end of each run of equal delta
};

PairOrder order_pairs(const Eigen::MatrixXd& delta) {
  PairOrder o;
  for (Eigen::Index i = 0; i < delta.rows(); ++i)
    for (Eigen::Index j = i + 1; j < delta.rows(); ++j) o.pairs.push_back({i, j});
  std::stable_sort(o.pairs.begin(), o.pairs.end(),
                   [&](const auto& a, const auto& b) { return delta(a.first, a.second) < delta(b.first, b.second); });
  for (std::size_t k = 1; k <= o.pairs.size(); ++k)
    if (k == o.pairs.size() || delta(o.pairs[k].first, o.pairs[k].second) != delta(o.pairs[k - 1].first, o.pairs[k - 1].second))
      o.tie_block_end.push_back(k);
  return o;
}

// Disparities for distances d: tied deltas are averaged first (secondary approach), then PAVA.
Eigen::MatrixXd disparities(const PairOrder& o, const Eigen::MatrixXd& d) {
  std::vector<double> y, w;
  std::size_t start = 0;
  for (std::size_t end : o.tie_block_end) {
    double s = 0;
    for (std::size_t k = start; k < end; ++k) s += d(o.pairs[k].first, o.pairs[k].second);
    // A tie block enters PAVA as one value repeated, weighting it by its size.
    for (std::size_t k = start; k < end; ++k) y.push_back(s / double(end - start));
    start = end;
  }
  const std::vector<double> fit = monotone_regression(y);
  const Eigen::Index n = d.rows();
  Eigen::MatrixXd dhat = Eigen::MatrixXd::Zero(n, n);
  double ss = 0;
  for (std::size_t k = 0; k < fit.size(); ++k) ss += fit[k] * fit[k];
  const double scale = std::sqrt(double(o.pairs.size()) / ss);  // sum dhat^2 = n(n-1)/2
  for (std::size_t k = 0; k < fit.size(); ++k)
    dhat(o.pairs[k].first, o.pairs[k].second) = dhat(o.pairs[k].second, o.pairs[k].first) = scale * fit[k];
  return dhat;
}

// Start `start` of a multi-start fit, centred: the classical solution first, then uniform draws.
Eigen::MatrixXd start_configuration(const Eigen::MatrixXd& dissimilarity, int dims, int start, std::mt19937_64& rng,
                                    std::uniform_real_distribution<double>& u) {
  Eigen::MatrixXd x;
  if (start == 0) {
    x = classical_mds(dissimilarity, dims).points;
  } else {
    x.resize(dissimilarity.rows(), dims);
    for (Eigen::Index i = 0; i < x.size(); ++i) x.data()[i] = u(rng);
  }
  x.rowwise() -= x.colwise().mean();
  return x;
}

double nonmetric_stress1(const Eigen::MatrixXd& dhat, const Eigen::MatrixXd& d) {
  return std::sqrt((d - dhat).squaredNorm() / d.squaredNorm());
}

}  // namespace

SmacofResult smacof_nonmetric(const Eigen::MatrixXd& dissimilarity, const SmacofOptions& options) {
  const Eigen::Index n = dissimilarity.rows();
  const PairOrder order = order_pairs(dissimilarity);
  SmacofResult best;
  best.stress1 = std::numeric_limits<double>::infinity();
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd bx(n, n);
  for (int start = 0; start <= options.random_starts; ++start) {
    Eigen::MatrixXd x = start_configuration(dissimilarity, options.dims, start, rng, u);
    // Start at the scale of the normalised disparities.
    x *= std::sqrt(double(order.pairs.size()) / (0.5 * pairwise_distances(x).squaredNorm()));
    Eigen::MatrixXd d = pairwise_distances(x);
    double stress = nonmetric_stress1(disparities(order, d), d);
    int iterations = 0;
    for (int it = 0; it < options.max_iterations; ++it) {
      const Eigen::MatrixXd dhat = disparities(order, d);
      for (Eigen::Index i = 0; i < n; ++i) {
        double diag = 0;
        for (Eigen::Index j = 0; j < n; ++j) {
          if (i == j) continue;
          bx(i, j) = d(i, j) > 0 ? -dhat(i, j) / d(i, j) : 0.0;
          diag -= bx(i, j);
        }
        bx(i, i) = diag;
      }
      x = bx * x / double(n);
      d = pairwise_distances(x);
      const double next = nonmetric_stress1(disparities(order, d), d);
      iterations = it + 1;
      const bool done = stress - next <= options.tolerance * stress;
      stress = next;
      if (done) break;
    }
    if (stress < best.stress1) {
      best.points = x;
      best.stress1 = stress;
      best.iterations = iterations;
      best.best_start = start;
    }
  }
  best.points.rowwise() -= best.points.colwise().mean();
  const Eigen::MatrixXd d = pairwise_distances(best.points);
  best.raw_stress = 0.5 * (d - disparities(order, d)).squaredNorm();
  return best;
}

SmacofResult smacof(const Eigen::MatrixXd& dissimilarity, const SmacofOptions& options) {
  SmacofResult best;
  best.raw_stress = std::numeric_limits<double>::infinity();
  std::mt19937_64 rng(options.seed);
  // Random starts are spread like the data: uniform in a cube of the dissimilarities' scale.
  const double scale = dissimilarity.maxCoeff();
  std::uniform_real_distribution<double> u(-scale, scale);
  for (int start = 0; start <= options.random_starts; ++start) {
    Eigen::MatrixXd x = start_configuration(dissimilarity, options.dims, start, rng, u);
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
