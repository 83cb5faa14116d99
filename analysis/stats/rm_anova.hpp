// Repeated-measures ANOVA (univariate approach, type III sums of squares) for any number of
// within-subject factors and optional between-subject factors, with sphericity diagnostics, as
// R's car::Anova(mlm, idata) and afex::aov_ez compute it.
//
// Method (multivariate formulation; O'Brien & Kaiser 1985; Fox & Weisberg, car):
//   Y (N subjects x C cells) holds cell means. A within term W (a set of within factors) has the
//   contrast matrix M_W = K_1 (x) ... (x) K_k (Kronecker product over the within factors in order)
//   with K_i = the l_i x (l_i - 1) normalised Helmert contrasts when factor i is in W and
//   1/sqrt(l_i) (a column of length l_i) otherwise, so M_W has orthonormal columns (q_W of them).
//   Z = Y M_W. Between terms T use sum-to-zero coded columns of the full-factorial between model
//   X (N x p); B = (X'X)^-1 X'Z.
//     hypothesis SSP  H = B_T' [((X'X)^-1)_TT]^-1 B_T      (type III: T tested given all others)
//     error SSP       E = Z'Z - B'X'Z,  df_e = N - p
//     SS = tr H, SS_err = tr E, df1 = q_W t_T, df2 = q_W df_e, F = (SS/df1)/(SS_err/df2),
//     p = P(F_{df1,df2} > F).
//   Effect T:W is named by its between then within factors ("G:A:B"); the intercept row is omitted.
// Sphericity (within terms with q > 1; the same for every between term crossed with W):
//   Greenhouse-Geisser  eps_GG = (tr E)^2 / (q tr(E^2))                       (Greenhouse & Geisser 1959)
//   Huynh-Feldt         eps_HF = ((df_e + 1) q eps_GG - 2) / (q (df_e - q eps_GG))
//                       (Lecoutre's 1991 correction of Huynh & Feldt 1976, as in car >= 3.0 and
//                       afex; reported uncapped, p_hf uses min(1, eps_HF))
//   corrected p: df1 and df2 multiplied by eps.
//   Mauchly's W = det(E) / (tr(E)/q)^q, chi-square approximation with the second-order term of
//   Anderson (1958) as in R's stats::mauchly.test: rho = 1 - (2q^2 + q + 2)/(6 q df_e),
//   z = -df_e rho log W, f = q(q+1)/2 - 1, w2 = (q+2)(q-1)(q-2)(2q^3+6q^2+3C+2)/(288 (df_e q rho)^2),
//   p = P1 + w2 (P2 - P1) with P1 = P(chi2_f > z), P2 = P(chi2_{f+4} > z). C is the number of
//   cells: R's code has "3 * p" with p the dimension of the untransformed response where Anderson
//   has q; we follow R so that the numbers agree with afex (the term only matters for q >= 3).
// Effect sizes (afex):
//   generalised eta^2 (Olejnik & Algina 2003; Bakeman 2005), all factors manipulated:
//     ges = SS / (SS + sum of the error SS of every stratum (subjects and every within term))
//   partial eta^2  pes = SS / (SS + SS_err).
// Cell means are scaled by a power of two first (exact; values like 1e300 work). An effect whose error
// SS is 0 within rounding (SS_err <= 1e-10 (SS + SS_err): F infinite or 0/0), or whose SS exceed the
// double range, throws std::domain_error naming the effect.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "analysis/stats/rm_data.hpp"

namespace ms {

struct RmEffect {
  std::string name;             // "A", "A:B", "G", "G:A"
  bool within = false;          // has a within-subject part
  double df1 = 0, df2 = 0;      // uncorrected degrees of freedom
  double ss = 0, ss_error = 0;  // sum of squares of the effect and of its error term
  double F = 0, p = 1;
  double ges = 0, pes = 0;
  std::optional<double> eps_gg, eps_hf;  // within effects only (1 when q = 1)
  double p_gg = 1, p_hf = 1;             // equal p when no correction applies
  std::optional<double> mauchly_w, mauchly_p;  // within effects with q > 1 and df_e >= q
};

struct RmAnova {
  std::vector<RmEffect> effects;
  std::size_t n_subjects = 0;
};

RmAnova rm_anova(const RmData& data);

// Orthonormal contrasts for a factor with `levels` levels: normalised Helmert, levels x (levels-1),
// columns orthogonal to each other and to the constant.
Eigen::MatrixXd orthonormal_contrasts(std::size_t levels);

// P(F_{df1,df2} > f), handling f = +inf (0) and f <= 0 (1).
double f_upper_p(double f, double df1, double df2);

}  // namespace ms
