#include "synthesis/reference_objects.hpp"

#include <algorithm>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/bessel_prime.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <numbers>
#include <numeric>

namespace ms {

namespace {

// 8-point Gauss-Legendre on [-1, 1]: nodes +-x, weights w.
constexpr double kGauss8x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                0.9602898564975363};
constexpr double kGauss8w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                0.1012285362903763};

template <class F>
double bracketed_root(F f, double lo, double hi) {
  boost::math::tools::eps_tolerance<double> tol(50);
  std::uintmax_t iterations = 200;
  auto r = boost::math::tools::toms748_solve(f, lo, hi, tol, iterations);
  return 0.5 * (r.first + r.second);
}

// Free-free bar mode shape at x (0..L) for root b = beta L, evaluated without overflow.
// phi = cos(u) - s sin(u) + cosh(u) - s sinh(u), u = b x/L, s = (cosh b - cos b)/(sinh b - sin b).
double bar_shape(double b, double x_rel) {
  const double u = b * x_rel;
  const double e = std::exp(-b);
  const double denom_scaled = 0.5 * (1.0 - e * e - 2.0 * std::sin(b) * e);  // (sinh b - sin b) e^-b
  const double one_minus_s_scaled = -(e - std::cos(b) + std::sin(b)) / denom_scaled;  // (1-s) e^b
  const double one_minus_s = one_minus_s_scaled * e;
  const double s = 1.0 - one_minus_s;
  // cosh u - s sinh u = ((1-s) e^u + (1+s) e^-u) / 2
  const double hyper = 0.5 * (one_minus_s_scaled * std::exp(u - b) + (1.0 + s) * std::exp(-u));
  return std::cos(u) - s * std::sin(u) + hyper;
}

}  // namespace

double free_bar_root(int n) {
  const double guess = (n + 0.5) * std::numbers::pi;
  auto f = [](double x) { return std::cos(x) - 1.0 / std::cosh(x); };
  return bracketed_root(f, guess - 0.5, guess + 0.5);
}

ObjectModes free_free_bar(double length_m, double thickness_m, const std::vector<double>& hit_positions,
                          double max_lambda0, std::size_t max_modes) {
  ObjectModes out;
  out.gains.resize(hit_positions.size());
  const double shape_factor = thickness_m * thickness_m / 12.0 / std::pow(length_m, 4);
  for (int n = 1; out.lambda0.size() < max_modes; ++n) {
    const double b = free_bar_root(n);
    const double lambda0 = std::pow(b, 4) * shape_factor;
    if (lambda0 > max_lambda0) break;
    out.lambda0.push_back(lambda0);
    for (std::size_t h = 0; h < hit_positions.size(); ++h)  // normalised: mean of phi^2 is 1
      out.gains[h].push_back(bar_shape(b, hit_positions[h]));
    out.circumferential_order.push_back(0);
  }
  return out;
}

namespace {

// Bessel functions in double precision: Boost's default promotes doubles to long double (x87), which
// made finding 2000 plate modes take most of a second; double keeps ~1e-15 relative accuracy.
using BesselPolicy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
double bessel_j(int n, double x) { return boost::math::cyl_bessel_j(n, x, BesselPolicy()); }
double bessel_j_prime(int n, double x) { return boost::math::cyl_bessel_j_prime(n, x, BesselPolicy()); }
double bessel_i(int n, double x) { return boost::math::cyl_bessel_i(n, x, BesselPolicy()); }
double bessel_i_prime(int n, double x) { return boost::math::cyl_bessel_i_prime(n, x, BesselPolicy()); }

struct PlateEquation {
  int n;
  double nu;
  // Cross-multiplied free-edge equation, I-terms divided by I_n(k) to stay finite.
  double operator()(double k) const {
    const double nn = double(n) * n;
    const double j = bessel_j(n, k), jp = bessel_j_prime(n, k);
    const double ri = bessel_i_prime(n, k) / bessel_i(n, k);
    const double num1 = k * k * j + (1 - nu) * (k * jp - nn * j);
    const double den1 = k * k - (1 - nu) * (k * ri - nn);
    const double num2 = k * k * k * jp + (1 - nu) * nn * (k * jp - j);
    const double den2 = k * k * k * ri - (1 - nu) * nn * (k * ri - 1);
    return num1 * den2 - num2 * den1;
  }
};

// Mode shape W(r) = J_n(k r) + C I_n(k r) of one root, C from zero radial moment at the edge;
// r in units of the radius.
struct PlateShape {
  int n;
  double k;
  double c_over_ik;  // C * I_n(k), so that C I_n(k r) = c_over_ik * I_n(k r) / I_n(k)
  double i_k;        // I_n(k)
  PlateShape(int order, double root, double nu) : n(order), k(root) {
    const double nn = double(n) * n;
    const double j = bessel_j(n, k), jp = bessel_j_prime(n, k);
    i_k = bessel_i(n, k);
    const double ri = bessel_i_prime(n, k) / i_k;
    const double num1 = k * k * j + (1 - nu) * (k * jp - nn * j);
    const double den1 = k * k - (1 - nu) * (k * ri - nn);
    c_over_ik = -num1 / den1;  // C * I_n(k)
  }
  double operator()(double r) const {
    return bessel_j(n, k * r) + c_over_ik * bessel_i(n, k * r) / i_k;
  }
};

}  // namespace

std::vector<double> free_plate_roots(int n, double poisson, double k_max) {
  PlateEquation eq{n, poisson};
  auto resolved = [n](double k) { return std::max(std::abs(bessel_j(n, k)), std::abs(bessel_j_prime(n, k))) > 1e-100; };
  std::vector<double> roots;
  const double step = 0.1;  // roots of one order are ~pi apart
  double k0 = 0.5, g0 = eq(k0);
  for (double k1 = k0 + step; k1 <= k_max + step; k1 += step) {
    const double g1 = eq(k1);
    // At high orders and small k, J_n and J_n' underflow (J_150(0.8) ~ 1e-320) and the equation is
    // rounding noise (or 0/0): its sign changes there are no roots (they lie above k = n).
    if (std::isfinite(g0) && std::isfinite(g1) && (g0 < 0) != (g1 < 0) && resolved(k0) && resolved(k1)) {
      const double r = bracketed_root(eq, k0, k1);
      if (r <= k_max) roots.push_back(r);
    }
    k0 = k1;
    g0 = g1;
  }
  return roots;
}

ObjectModes free_circular_plate(double radius_m, double thickness_m, double poisson,
                                const std::vector<double>& hit_radii, double max_lambda0,
                                std::size_t max_modes) {
  // omega^2 = k^4 / a^4 * D/(rho h) with D/(rho h) = (E/rho) h^2 / (12 (1 - nu^2)).
  const double stiffness = thickness_m * thickness_m / (12.0 * (1.0 - poisson * poisson));
  const double a4 = std::pow(radius_m, 4);
  // k is capped at 600 (about the 90,000th mode), where I_n(k) nears the double range.
  const double k_max = std::min(600.0, std::pow(max_lambda0 * a4 / stiffness, 0.25));
  // Roots of every order below k_max; once max_modes are known, k_max shrinks to the largest of
  // the max_modes smallest roots (the first root of order n grows with n, so the scan ends).
  struct Root {
    double k;
    int n;
  };
  std::vector<Root> roots_found;
  double k_limit = k_max;
  for (int n = 0;; ++n) {
    const auto roots = free_plate_roots(n, poisson, k_limit);
    if (roots.empty() && n > 2) break;
    for (double k : roots) roots_found.push_back({k, n});
    std::sort(roots_found.begin(), roots_found.end(), [](const Root& a, const Root& b) { return a.k < b.k; });
    if (roots_found.size() > max_modes) {
      roots_found.resize(max_modes);
      k_limit = roots_found.back().k;
    }
  }
  struct Entry {
    double lambda0;
    std::vector<double> gains;
    int n;
  };
  std::vector<Entry> entries;
  for (const Root& root : roots_found) {
    const PlateShape shape(root.n, root.k, poisson);
    // Mass normalisation: mean of W^2 cos^2(n theta) over the disc is 1. int_0^1 W^2 r dr by
    // 8-point Gauss-Legendre on panels short enough for the oscillation of J_n(k r).
    const int panels = int(std::ceil(root.k / 2.0)) + 2;
    double integral = 0.0;
    for (int p = 0; p < panels; ++p) {
      const double lo = double(p) / panels, h = 1.0 / panels;
      for (std::size_t q = 0; q < 4; ++q)
        for (double sign : {-1.0, 1.0}) {
          const double r = lo + 0.5 * h * (1.0 + sign * kGauss8x[q]);
          const double w = shape(r);
          integral += 0.5 * h * kGauss8w[q] * w * w * r;
        }
    }
    const double angular = (root.n == 0) ? 1.0 : 0.5;  // mean of cos^2(n theta)
    const double norm = std::sqrt(2.0 * integral * angular);
    Entry e{std::pow(root.k, 4) * stiffness / a4, {}, root.n};
    for (double r : hit_radii) e.gains.push_back(shape(r) / norm);
    entries.push_back(std::move(e));
  }
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.lambda0 < b.lambda0; });
  ObjectModes out;
  out.gains.resize(hit_radii.size());
  for (const auto& e : entries) {
    if (out.lambda0.size() >= max_modes) break;
    out.lambda0.push_back(e.lambda0);
    for (std::size_t h = 0; h < hit_radii.size(); ++h) out.gains[h].push_back(e.gains[h]);
    out.circumferential_order.push_back(e.n);
  }
  return out;
}

}  // namespace ms
