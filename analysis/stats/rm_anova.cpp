#include "analysis/stats/rm_anova.hpp"

#include <algorithm>
#include <bit>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ms {

Eigen::MatrixXd orthonormal_contrasts(std::size_t levels) {
  const Eigen::Index l = Eigen::Index(levels);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(l, l - 1);
  for (Eigen::Index j = 1; j < l; ++j) {
    // Column j-1 contrasts level j with the mean of levels 0..j-1.
    const double norm = std::sqrt(double(j) * double(j + 1));
    k.col(j - 1).head(j).setConstant(-1.0 / norm);
    k(j, j - 1) = double(j) / norm;
  }
  return k;
}

double f_upper_p(double f, double df1, double df2) {
  if (std::isnan(f)) return std::numeric_limits<double>::quiet_NaN();
  if (f <= 0) return 1.0;
  if (std::isinf(f)) return 0.0;
  return boost::math::cdf(boost::math::complement(boost::math::fisher_f(df1, df2), f));
}

namespace {

double chi2_upper_p(double x, double df) {
  if (!(x > 0)) return 1.0;
  if (std::isinf(x)) return 0.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(df), x));
}

// Terms of the full factorial over `k` factors as bit masks, in R's order: by degree, then by
// mask value (A*B*C -> A, B, C, A:B, A:C, B:C, A:B:C). Mask 0 (the intercept) comes first.
std::vector<unsigned> factorial_terms(std::size_t k) {
  std::vector<unsigned> t;
  for (unsigned m = 0; m < (1u << k); ++m) t.push_back(m);
  std::stable_sort(t.begin(), t.end(), [](unsigned a, unsigned b) { return std::popcount(a) < std::popcount(b); });
  return t;
}

std::string term_name(const std::vector<RmFactor>& factors, unsigned mask) {
  std::string s;
  for (std::size_t i = 0; i < factors.size(); ++i)
    if (mask & (1u << i)) s += (s.empty() ? "" : ":") + factors[i].name;
  return s;
}

Eigen::MatrixXd kron(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  Eigen::MatrixXd k(a.rows() * b.rows(), a.cols() * b.cols());
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j) k.block(i * b.rows(), j * b.cols(), b.rows(), b.cols()) = a(i, j) * b;
  return k;
}

// Within contrast matrix M_W (cells x q): Kronecker product in factor order, first factor slowest,
// matching the row-major cell index of RmData.
Eigen::MatrixXd within_contrasts(const std::vector<RmFactor>& within, unsigned mask) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Ones(1, 1);
  for (std::size_t i = 0; i < within.size(); ++i) {
    const std::size_t l = within[i].levels.size();
    const Eigen::MatrixXd k = (mask & (1u << i)) ? orthonormal_contrasts(l)
                                                 : Eigen::MatrixXd::Constant(Eigen::Index(l), 1, 1.0 / std::sqrt(double(l)));
    m = kron(m, k);
  }
  return m;
}

// Sum-to-zero codes of one between factor: level j < l-1 -> e_j, the last level -> -1 everywhere.
Eigen::RowVectorXd sum_code(std::size_t levels, int level) {
  Eigen::RowVectorXd c = Eigen::RowVectorXd::Zero(Eigen::Index(levels - 1));
  if (std::size_t(level) + 1 == levels) c.setConstant(-1.0);
  else c(level) = 1.0;
  return c;
}

}  // namespace

RmAnova rm_anova(const RmData& data) {
  const Eigen::Index n = data.cell_mean.rows();
  // Cell means scaled by a power of two near the largest |mean|: exact, and squares of values like
  // 1e300 stay finite (F, p, epsilons and effect sizes do not depend on it; SS are scaled back).
  const double max_abs = data.cell_mean.size() ? data.cell_mean.cwiseAbs().maxCoeff() : 0.0;
  const double scale = max_abs > 0 && std::isfinite(max_abs) ? std::ldexp(1.0, std::ilogb(max_abs)) : 1.0;
  const Eigen::MatrixXd y = data.cell_mean / scale;
  const auto within_terms = factorial_terms(data.within.size());
  const auto between_terms = factorial_terms(data.between.size());

  // Between model matrix X: per term, the row-wise Kronecker product of the factors' sum codes.
  std::vector<Eigen::Index> term_first, term_cols;
  Eigen::Index p = 0;
  for (unsigned t : between_terms) {
    Eigen::Index cols = 1;
    for (std::size_t f = 0; f < data.between.size(); ++f)
      if (t & (1u << f)) cols *= Eigen::Index(data.between[f].levels.size() - 1);
    term_first.push_back(p);
    term_cols.push_back(cols);
    p += cols;
  }
  Eigen::MatrixXd x(n, p);
  for (Eigen::Index s = 0; s < n; ++s)
    for (std::size_t ti = 0; ti < between_terms.size(); ++ti) {
      Eigen::MatrixXd row = Eigen::MatrixXd::Ones(1, 1);
      for (std::size_t f = 0; f < data.between.size(); ++f)
        if (between_terms[ti] & (1u << f))
          row = kron(row, sum_code(data.between[f].levels.size(), data.between_level(s, Eigen::Index(f))));
      x.block(s, term_first[ti], 1, term_cols[ti]) = row;
    }
  const Eigen::MatrixXd xtx_inv = (x.transpose() * x).ldlt().solve(Eigen::MatrixXd::Identity(p, p));
  const double df_e = double(n - p);
  // Per between term: [((X'X)^-1)_TT]^-1, reused for every within term.
  std::vector<Eigen::MatrixXd> v_inv;
  for (std::size_t ti = 0; ti < between_terms.size(); ++ti)
    v_inv.push_back(xtx_inv.block(term_first[ti], term_first[ti], term_cols[ti], term_cols[ti])
                        .ldlt()
                        .solve(Eigen::MatrixXd::Identity(term_cols[ti], term_cols[ti])));

  RmAnova out;
  out.n_subjects = std::size_t(n);
  double error_ss_all_strata = 0.0;
  for (unsigned w : within_terms) {
    const Eigen::MatrixXd m = within_contrasts(data.within, w);
    const Eigen::Index q = m.cols();
    const Eigen::MatrixXd z = y * m;
    const Eigen::MatrixXd b = xtx_inv * (x.transpose() * z);
    const Eigen::MatrixXd resid = z - x * b;
    const Eigen::MatrixXd e = resid.transpose() * resid;
    const double ss_err = e.trace();
    error_ss_all_strata += ss_err;

    // Sphericity, shared by every between term crossed with w.
    std::optional<double> eps_gg, eps_hf, mauchly_w, mauchly_p;
    if (w != 0) {
      const double qd = double(q);
      const double gg = q == 1 ? 1.0 : ss_err * ss_err / (qd * (e * e).trace());
      eps_gg = gg;
      eps_hf = ((df_e + 1) * qd * gg - 2) / (qd * (df_e - qd * gg));
      if (q > 1 && df_e >= qd) {
        // A singular E (rank below q) has W = 0.
        const double det = e.determinant();
        const double log_w = det > 0 ? std::log(det) - qd * std::log(ss_err / qd) : -std::numeric_limits<double>::infinity();
        const double rho = 1 - (2 * qd * qd + qd + 2) / (6 * qd * df_e);
        // R (stats::mauchly.test and car) writes 3p with p = the number of cells here, not q.
        const double cells = double(m.rows());
        const double w2 = (qd + 2) * (qd - 1) * (qd - 2) * (2 * qd * qd * qd + 6 * qd * qd + 3 * cells + 2) /
                          (288 * std::pow(df_e * qd * rho, 2));
        const double zstat = -df_e * rho * log_w;
        const double f = qd * (qd + 1) / 2 - 1;
        const double p1 = chi2_upper_p(zstat, f), p2 = chi2_upper_p(zstat, f + 4);
        mauchly_w = std::exp(log_w);
        mauchly_p = p1 + w2 * (p2 - p1);
      }
    }
    for (std::size_t ti = 0; ti < between_terms.size(); ++ti) {
      const unsigned t = between_terms[ti];
      if (t == 0 && w == 0) continue;  // intercept
      const auto bt = b.middleRows(term_first[ti], term_cols[ti]);
      const double ss = (bt.transpose() * v_inv[ti] * bt).trace();
      RmEffect eff;
      const std::string bn = term_name(data.between, t), wn = term_name(data.within, w);
      eff.name = bn.empty() ? wn : wn.empty() ? bn : bn + ":" + wn;
      eff.within = w != 0;
      eff.df1 = double(q * term_cols[ti]);
      eff.df2 = double(q) * df_e;
      eff.ss = ss;
      eff.ss_error = ss_err;
      // No error variance (within rounding, as car::Anova refuses it): F would be infinite or 0/0.
      if (!(ss_err > 1e-10 * (ss + ss_err)))
        throw std::domain_error("effect " + eff.name + ": the error sum of squares is 0 (every subject shows the same "
                                "values up to a constant): F is undefined");
      eff.F = (ss / eff.df1) / (ss_err / eff.df2);
      eff.p = f_upper_p(eff.F, eff.df1, eff.df2);
      eff.pes = ss / (ss + ss_err);
      eff.eps_gg = eps_gg;
      eff.eps_hf = eps_hf;
      eff.mauchly_w = mauchly_w;
      eff.mauchly_p = mauchly_p;
      eff.p_gg = eps_gg ? f_upper_p(eff.F, eff.df1 * *eps_gg, eff.df2 * *eps_gg) : eff.p;
      const double hf = eps_hf ? std::min(1.0, *eps_hf) : 1.0;
      eff.p_hf = f_upper_p(eff.F, eff.df1 * hf, eff.df2 * hf);
      out.effects.push_back(eff);
    }
  }
  for (auto& eff : out.effects) {
    eff.ges = eff.ss / (eff.ss + error_ss_all_strata);
    eff.ss *= scale * scale;
    eff.ss_error *= scale * scale;
    if (!std::isfinite(eff.ss) || !std::isfinite(eff.ss_error))
      throw std::domain_error("effect " + eff.name + ": its sums of squares exceed the range of double precision "
                              "(rescale the dependent variable)");
  }
  return out;
}

}  // namespace ms
