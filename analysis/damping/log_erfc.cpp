// log erfc and erfcx: direct evaluation where erfc is representable, a continued fraction beyond.
#include "analysis/damping/log_erfc.hpp"

#include <cmath>
#include <limits>

namespace ms {

namespace {

constexpr double kInvSqrtPi = 0.56418958354775628695;  // 1/sqrt(pi)
// Beyond this erfc(x) (~5.7e-296 at 26) would become subnormal/zero; exp(x^2) still fits.
constexpr double kDirectLimit = 26.0;

// exp(x^2) with x^2 split into hi + lo (fma), so the rounding of x^2 (relative eps, i.e. an absolute
// error of x^2 eps in the exponent) does not cost ~x^2 ulps of accuracy.
double exp_square(double x) {
  const double hi = x * x;
  const double lo = std::fma(x, x, -hi);
  return std::exp(hi) * (1.0 + lo);
}

// erfcx(x) for x >= 26 by the Laplace continued fraction
//   erfc(x) = exp(-x^2)/sqrt(pi) * 1/(x + (1/2)/(x + 1/(x + (3/2)/(x + ...)))),
// evaluated backwards; at x >= 26 twelve levels are far below double precision (terms ~ k/(2x^2)).
double erfcx_continued_fraction(double x) {
  double f = x;
  for (int k = 12; k >= 1; --k) f = x + 0.5 * k / f;
  return kInvSqrtPi / f;
}

}  // namespace

double erfcx(double x) {
  if (x < kDirectLimit) return exp_square(x) * std::erfc(x);  // x < 0: erfc in (1, 2], may overflow to inf
  return erfcx_continued_fraction(x);
}

double log_erfc(double x) {
  if (x < kDirectLimit) return std::log(std::erfc(x));
  return -x * x + std::log(erfcx_continued_fraction(x));
}

void log_erfc_with_slope(double x, double* log_erfc_out, double* slope_out) {
  if (x < kDirectLimit) {
    const double e = std::erfc(x);
    *log_erfc_out = std::log(e);
    // For x << 0, exp(x^2) overflows to inf and the slope correctly becomes -0.
    *slope_out = -2.0 * kInvSqrtPi / (exp_square(x) * e);
  } else {
    const double ex = erfcx_continued_fraction(x);
    *log_erfc_out = -x * x + std::log(ex);
    *slope_out = -2.0 * kInvSqrtPi / ex;
  }
}

}  // namespace ms
