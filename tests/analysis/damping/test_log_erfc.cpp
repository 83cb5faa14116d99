// log erfc / erfcx at small and huge arguments: against Boost.Math in extended precision where erfc is
// still representable in long double, and against the asymptotic series where nothing else is.
#include <gtest/gtest.h>

#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <numbers>

#include "analysis/damping/log_erfc.hpp"

namespace {

// log erfcx(x) = log erfc(x) + x^2 from the asymptotic series erfc(x) ~ e^{-x^2}/(x sqrt(pi)) sum_k (-1)^k (2k-1)!!/(2x^2)^k,
// summed (in long double) until the terms stop shrinking.
long double log_erfcx_asymptotic(long double x) {
  long double term = 1.0L, sum = 1.0L;
  for (int k = 1; k < 60; ++k) {
    const long double next = -term * (2.0L * k - 1.0L) / (2.0L * x * x);
    if (std::fabs(next) >= std::fabs(term)) break;
    term = next;
    sum += term;
  }
  return -std::log(x * std::sqrt(3.14159265358979323846264338327950288L)) + std::log(sum);
}
long double log_erfc_asymptotic(long double x) { return -x * x + log_erfcx_asymptotic(x); }

TEST(LogErfc, MatchesBoostWhereErfcIsRepresentable) {
  for (double x : {-30.0, -5.0, -1.0, -1e-3, 0.0, 0.3, 1.0, 3.0, 8.0, 20.0, 25.9, 26.0, 26.1}) {
    const double expected = std::log(boost::math::erfc(x));
    EXPECT_NEAR(ms::log_erfc(x), expected, 4e-15 * std::max(1.0, std::abs(expected))) << "x=" << x;
  }
}

TEST(LogErfc, ExtendedPrecisionBeyondDoubleUnderflow) {
  // erfc(30) ~ 1e-393 and erfc(100) ~ 1e-4345 underflow in double but not in long double (x87).
  for (double x : {27.0, 30.0, 45.0, 100.0}) {
    const long double expected = std::log(boost::math::erfc(static_cast<long double>(x)));
    ASSERT_TRUE(std::isfinite(expected));
    EXPECT_NEAR(ms::log_erfc(x), static_cast<double>(expected), 2e-15 * std::abs(static_cast<double>(expected)))
        << "x=" << x;
  }
}

TEST(LogErfc, LargeArgumentsFiniteAndMatchAsymptoticSeries) {
  for (double x : {30.0, 1e3, 1e6}) {
    const double got = ms::log_erfc(x);
    ASSERT_TRUE(std::isfinite(got)) << "x=" << x;
    const double expected = static_cast<double>(log_erfc_asymptotic(x));
    EXPECT_NEAR(got, expected, 2e-15 * std::abs(expected)) << "x=" << x;
    // Beyond -x^2 the remainder is log erfcx(x) ~ -log(x sqrt(pi)); check it through erfcx, since in
    // log_erfc(1e6) the -x^2 = -1e12 term leaves only ~1e-4 absolute resolution for it.
    const double expected_log_erfcx = static_cast<double>(log_erfcx_asymptotic(x));
    EXPECT_NEAR(std::log(ms::erfcx(x)), expected_log_erfcx, 1e-14 * std::abs(expected_log_erfcx)) << "x=" << x;
  }
}

TEST(LogErfc, SlopeIsDerivativeAndErfcxIsScaledErfc) {
  for (double x : {-40.0, -3.0, -0.5, 0.0, 0.7, 4.0, 25.0, 26.5, 30.0, 1e3, 1e6}) {
    double le = 0, slope = 0;
    ms::log_erfc_with_slope(x, &le, &slope);
    EXPECT_EQ(le, ms::log_erfc(x));
    EXPECT_NEAR(slope, -2.0 / (std::sqrt(std::numbers::pi) * ms::erfcx(x)), 1e-15 * std::abs(slope) + 1e-300);
    if (x > -20 && x < 1e5) {  // central difference, relative step
      const double h = 1e-5 * std::max(1.0, std::abs(x));
      const double fd = (ms::log_erfc(x + h) - ms::log_erfc(x - h)) / (2 * h);
      EXPECT_NEAR(slope, fd, 1e-7 * std::max(1.0, std::abs(fd))) << "x=" << x;
    }
    if (x > -26 && x < 100) {  // erfcx against Boost in long double
      const long double xl = x;
      const long double expected = std::exp(xl * xl) * boost::math::erfc(xl);
      EXPECT_NEAR(ms::erfcx(x), static_cast<double>(expected), 1e-14 * static_cast<double>(expected))
          << "x=" << x;
    }
  }
  double le = 0, slope = 1;
  ms::log_erfc_with_slope(-1e3, &le, &slope);  // far above the curve: erfc = 2, t -> 0
  EXPECT_EQ(slope, 0.0);
  EXPECT_NEAR(le, std::log(2.0), 1e-15);
}

}  // namespace
