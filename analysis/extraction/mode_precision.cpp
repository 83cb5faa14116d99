// Cramer-Rao bounds of the damped-sinusoid parameters; see mode_precision.hpp.
#include "analysis/extraction/mode_precision.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>

namespace ms {

std::vector<ModePrecision> mode_precision(const std::vector<DampedComponent>& c, std::size_t frames,
                                          double fs, double noise_sigma, double amp_origin_offset) {
  const std::size_t K = c.size();
  std::vector<ModePrecision> out(K);
  if (K == 0) return out;
  // Parameters per component: Re b, Im b, Re s, Im s (s per sample). Scaling the Gram to unit
  // diagonal keeps the inversion well conditioned across 60 dB of amplitudes and decades of decay.
  Eigen::MatrixXd A = pole_gram(c, frames);
  const Eigen::VectorXd scale = A.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  A = scale.asDiagonal() * A * scale.asDiagonal();
  const Eigen::Index P = A.rows();
  const double inf = std::numeric_limits<double>::infinity();
  // Covariance of a combination g of the (scaled) parameters is g^T A^-1 g sigma^2. Cholesky when A
  // is numerically positive definite (the usual case, P^3/3 flops); otherwise an eigen-decomposition,
  // where directions the data do not constrain (eigenvalue at the rounding of the largest) make the
  // variance of every parameter they touch infinite.
  Eigen::MatrixXd inverse;
  Eigen::VectorXd inv_w;
  Eigen::MatrixXd V;
  const Eigen::LLT<Eigen::MatrixXd> llt(A);
  const bool definite = llt.info() == Eigen::Success && llt.matrixLLT().diagonal().minCoeff() > 1e-7;
  if (definite) {
    inverse = llt.solve(Eigen::MatrixXd::Identity(P, P));
  } else {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
    const Eigen::VectorXd& w = eig.eigenvalues();
    V = eig.eigenvectors();
    const double cutoff = 1e-13 * w.maxCoeff();
    inv_w.resize(w.size());
    for (Eigen::Index i = 0; i < w.size(); ++i) inv_w(i) = w(i) > cutoff ? 1.0 / w(i) : inf;
  }
  // g: the combination's weights on component r / 4's four parameters (rows r..r+3).
  auto variance = [&](Eigen::Index r, const Eigen::Vector4d& g) {
    if (definite) return g.dot(inverse.block<4, 4>(r, r) * g) * noise_sigma * noise_sigma;
    double v = 0.0;
    const double touch = 1e-6 * g.norm();
    for (Eigen::Index i = 0; i < inv_w.size(); ++i) {
      const double p = V.block<4, 1>(r, i).dot(g);
      if (p != 0.0) v += (std::isinf(inv_w(i)) ? (std::abs(p) > touch ? inf : 0.0) : p * p * inv_w(i));
    }
    return v * noise_sigma * noise_sigma;
  };
  for (std::size_t k = 0; k < K; ++k) {
    const Eigen::Index r = Eigen::Index(4 * k);
    out[k].freq_sd_hz = std::sqrt(variance(r, {0.0, 0.0, 0.0, scale(r + 3)})) * fs / (2.0 * std::numbers::pi);
    out[k].decay_sd_per_s = std::sqrt(variance(r, {0.0, 0.0, scale(r + 2), 0.0})) * fs;
    // amp at -offset = |b| e^{-Re(s) offset}: gradient (Re b, Im b) / |b| times that factor, and
    // -offset times that amplitude along Re s.
    const double mag = std::abs(c[k].b), grow = std::exp(-c[k].s.real() * amp_origin_offset);
    Eigen::Vector4d g(0.0, 0.0, -amp_origin_offset * mag * grow * scale(r + 2), 0.0);
    if (mag > 0.0) {
      g(0) = c[k].b.real() / mag * grow * scale(r);
      g(1) = c[k].b.imag() / mag * grow * scale(r + 1);
    }
    out[k].amp_sd = std::sqrt(variance(r, g));
  }
  return out;
}

}  // namespace ms
