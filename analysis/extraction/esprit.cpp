// ESPRIT in covariance form; see esprit.hpp. Eigen does the Hermitian and general eigenproblems.
#include "analysis/extraction/esprit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace ms {

std::vector<std::complex<double>> esprit(const std::complex<double>* y, std::size_t length,
                                         const EspritOptions& options) {
  using cd = std::complex<double>;
  std::vector<cd> poles;
  std::size_t m = std::min(options.window, length / 2);
  if (m < 4) return poles;
  const std::size_t rows = length - m + 1;
  // R[a][b] = sum_{i<rows} conj(y[i+a]) y[i+b]; first row directly, then
  // R[a+1][b+1] = R[a][b] - conj(y[a]) y[b] + conj(y[a+rows]) y[b+rows].
  Eigen::MatrixXcd R(m, m);
  for (std::size_t b = 0; b < m; ++b) {
    // Spelled out in reals: std::complex's multiply carries inf/nan checks that stop vectorisation.
    double re = 0.0, im = 0.0;
    for (std::size_t i = 0; i < rows; ++i) {
      const double ar = y[i].real(), ai = y[i].imag(), br = y[i + b].real(), bi = y[i + b].imag();
      re += ar * br + ai * bi;
      im += ar * bi - ai * br;
    }
    R(0, Eigen::Index(b)) = cd(re, im);
  }
  for (std::size_t a = 0; a + 1 < m; ++a)
    for (std::size_t b = a; b + 1 < m; ++b)
      R(Eigen::Index(a + 1), Eigen::Index(b + 1)) =
          R(Eigen::Index(a), Eigen::Index(b)) - std::conj(y[a]) * y[b] +
          std::conj(y[a + rows]) * y[b + rows];
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = 0; b < a; ++b)
      R(Eigen::Index(a), Eigen::Index(b)) = std::conj(R(Eigen::Index(b), Eigen::Index(a)));

  // Eigenvalues only (the eigenvectors of all m would cost three times as much): the order first.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> eig(R, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& lambda = eig.eigenvalues();  // ascending
  // Marchenko-Pastur-like edge for the noise eigenvalues, times a safety factor.
  const double edge = std::pow(1.0 + std::sqrt(double(m) / double(rows)), 2.0);
  double noise_power = options.noise_power;
  if (options.own_noise_factor > 0.0)
    noise_power = std::max(noise_power, options.own_noise_factor * lambda(Eigen::Index(m / 2)) / double(rows));
  const double threshold = options.threshold_factor * edge * double(rows) * noise_power;
  std::size_t order = 0;
  for (Eigen::Index i = Eigen::Index(m) - 1; i >= 0; --i)
    if (lambda(i) > threshold) ++order;
  order = std::min({order, options.max_order, m - 2});
  if (order == 0) return poles;

  const Eigen::Index K = Eigen::Index(order), M = Eigen::Index(m);
  // Signal subspace by block power iteration with a few spare columns, then Rayleigh-Ritz: the
  // noise eigenvalues lie at least threshold_factor below the signal ones, so a few products with R
  // converge, and shift invariance needs only a basis of the subspace.
  const Eigen::Index B = std::min(M, K + 4);
  Eigen::MatrixXcd Y(M, B);
  for (Eigen::Index a = 0; a < M; ++a)  // fixed pseudo-random start (golden-ratio phases)
    for (Eigen::Index b = 0; b < B; ++b)
      Y(a, b) = std::polar(1.0, 2.0 * std::numbers::pi * std::fmod(0.6180339887 * double((a + 1) * (b + 3)), 1.0));
  Eigen::MatrixXcd Q;
  for (int it = 0; it < 5; ++it) {
    Y = R * Y;
    Q = Eigen::HouseholderQR<Eigen::MatrixXcd>(Y).householderQ() * Eigen::MatrixXcd::Identity(M, B);
    Y = Q;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> ritz(Q.adjoint() * R * Q);
  // Right singular vectors of H span conj(Vandermonde(z)); shift invariance gives conj(z).
  const Eigen::MatrixXcd V = Q * ritz.eigenvectors().rightCols(K);
  const Eigen::MatrixXcd up = V.topRows(M - 1), down = V.bottomRows(M - 1);
  const Eigen::MatrixXcd psi = up.colPivHouseholderQr().solve(down);
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> ces(psi, false);
  poles.reserve(order);
  for (Eigen::Index k = 0; k < K; ++k) poles.push_back(std::conj(ces.eigenvalues()(k)));
  return poles;
}

}  // namespace ms
