// Numerically safe log erfc(x) and the scaled erfcx(x) = exp(x^2) erfc(x) for any real x, as needed
// by the EMG likelihood where s = (c(lambda) + eta sigma^2 - c) / (sqrt 2 sigma) can be huge.
#pragma once

namespace ms {

// erfcx(x) = exp(x^2) erfc(x). Finite for x >= -26.6 (overflows to +inf below, correctly).
double erfcx(double x);

// log(erfc(x)); for x >= 26 (where erfc underflows) -x^2 + log(erfcx(x)). Finite up to |x| ~ 1e154.
double log_erfc(double x);

// Both at once, for the likelihood's inner loop: *log_erfc_out = log erfc(x) and
// *slope_out = d/dx log erfc(x) = -2 / (sqrt(pi) erfcx(x))   (Sterling et al. 2019, t_i of eq. 1.11).
void log_erfc_with_slope(double x, double* log_erfc_out, double* slope_out);

}  // namespace ms
