// Sensitivity d' for the discrimination designs of A/B blocks (Macmillan & Creelman, Detection
// Theory: A User's Guide, 2nd ed. 2005). Phi is the standard normal CDF, z its inverse.
//
//   yes-no:          d' = z(H) - z(F)                                             (ch. 1)
//   2AFC (unbiased): p_c = Phi(d'/sqrt2)  <=>  d' = sqrt2 z(p_c)                   (ch. 7)
//   ABX, differencing model (Macmillan, Kaplan & Creelman 1977; ch. 9):
//                    p_c = Phi(d'/sqrt2) Phi(d'/2) + Phi(-d'/sqrt2) Phi(-d'/2), inverted numerically
//   same-different, differencing model (ch. 9): the observer says "different" when |x1 - x2| > k:
//                    F = 2 Phi(-k/sqrt2),  H = Phi((d' - k)/sqrt2) + Phi((-d' - k)/sqrt2);
//                    k follows from F in closed form, d' from H numerically.
// Rates of 0 or 1 give infinite d'; callers correct them first, e.g. with 1/(2N) and 1 - 1/(2N)
// (Macmillan & Kaplan 1985), see corrected_rate().
// p_c <= 1/2 (or H <= F) is chance performance and maps to d' = 0 for ABX and same-different, whose
// p_c is symmetric in d'.
#pragma once

namespace ms {

double normal_cdf(double x);
double normal_quantile(double p);

double dprime_yes_no(double hit_rate, double false_alarm_rate);
double pc_2afc(double dprime);
double dprime_2afc(double pc);
double pc_abx(double dprime);
double dprime_abx(double pc);

struct SameDifferent {
  double dprime = 0;
  double criterion_k = 0;  // the differencing criterion on |x1 - x2|
};
double hit_rate_same_different(double dprime, double criterion_k);
SameDifferent dprime_same_different(double hit_rate, double false_alarm_rate);

// Rate k/n, moved to 1/(2n) or 1 - 1/(2n) when it is 0 or 1.
double corrected_rate(double k, double n);

}  // namespace ms
