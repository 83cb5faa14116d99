// EMG log-likelihood with analytic derivatives. Per point, with r = y - m, s = (eta sigma^2 - r)/(sqrt2 sigma),
//   l = log eta - log 2 - eta r + eta^2 sigma^2 / 2 + log erfc(s)                          (eq. 1.10)
// and t = d log erfc / ds = -2/(sqrt(pi) erfcx(s)) (eq. 1.11), d t/ds = -2 s t - t^2. Derivatives are taken
// in (m, log sigma, log eta) and chained to the law parameters. In sigma itself this gives eqs. 1.12-1.15
// with d/dsigma of n eta^2 sigma^2 / 2 = n eta^2 sigma (the printed "n lambda^2 sigma" is a misprint).
#include "analysis/damping/emg_likelihood.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/damping/log_erfc.hpp"

namespace ms {

namespace {
constexpr double kSqrt1_2 = 0.70710678118654752440;
constexpr double kLn2 = 0.69314718055994530942;
}  // namespace

double damping_c_per_s(const DampingLaw& law, double lambda_rad2_s2) {
  return 2.0 * law.decay_per_s(lambda_rad2_s2);
}

double emg_log_likelihood(const std::vector<DampingPoint>& points, const DampingLaw& law,
                          double sigma_per_s, double eta_s) {
  double sum = 0.0;
  for (const auto& p : points) {
    const double model = damping_c_per_s(law, p.lambda_rad2_s2);
    const double s = (model + eta_s * sigma_per_s * sigma_per_s - p.c_per_s) * kSqrt1_2 / sigma_per_s;
    sum += std::log(eta_s / 2.0) +
           0.5 * eta_s * (2.0 * model + eta_s * sigma_per_s * sigma_per_s - 2.0 * p.c_per_s) + log_erfc(s);
  }
  return sum;
}

int law_param_count(DampingKind law) {
  switch (law) {
    case DampingKind::rayleigh: return 2;
    case DampingKind::powerlaw: return 2;
    case DampingKind::hybrid: return 3;
    case DampingKind::constant_q:
    case DampingKind::relaxation: break;
  }
  throw std::invalid_argument("damping fit supports the rayleigh, powerlaw and hybrid laws");
}

EmgProblem make_emg_problem(const std::vector<DampingPoint>& points, DampingKind law) {
  law_param_count(law);  // validates the law
  EmgProblem pr;
  pr.law = law;
  if (points.empty()) return pr;
  double lambda_max = 0.0;
  std::vector<double> cs;
  cs.reserve(points.size());
  for (const auto& p : points) {
    lambda_max = std::max(lambda_max, p.lambda_rad2_s2);
    cs.push_back(p.c_per_s);
  }
  std::nth_element(cs.begin(), cs.begin() + std::ptrdiff_t(cs.size() / 2), cs.end());
  const double c_median = cs[cs.size() / 2];
  pr.lambda_scale = lambda_max > 0 ? lambda_max : 1.0;
  pr.c_scale = c_median > 0 ? c_median : 1.0;
  pr.x.reserve(points.size());
  for (const auto& p : points) {
    pr.x.push_back(p.lambda_rad2_s2 / pr.lambda_scale);
    pr.y.push_back(p.c_per_s / pr.c_scale);
    pr.log_x.push_back(std::log(pr.x.back()));
  }
  return pr;
}

double emg_loglik_scaled(const EmgProblem& pr, const EmgVector& theta, EmgVector* gradient,
                         EmgMatrix* hessian) {
  const int k = law_param_count(pr.law);
  const int np = k + 2;
  const double log_sigma = theta[k], log_eta = theta[k + 1];
  const double sigma = std::exp(log_sigma), eta = std::exp(log_eta);
  const double a = pr.law == DampingKind::powerlaw ? 0.0 : theta[0];
  const double b = pr.law == DampingKind::powerlaw ? theta[0] : theta[1];
  const double p = pr.law == DampingKind::rayleigh ? 1.0 : theta[k - 1];

  const bool want_g = gradient != nullptr, want_h = hessian != nullptr;
  // Law-parameter accumulators (index 0..k-1) and the (log sigma, log eta) block.
  double g_law[3] = {0, 0, 0}, h_law[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  double h_law_ls[3] = {0, 0, 0}, h_law_le[3] = {0, 0, 0};
  double g_ls = 0, g_le = 0, h_ls_ls = 0, h_ls_le = 0, h_le_le = 0;
  double sum = 0.0;
  const std::size_t n = pr.x.size();

  for (std::size_t i = 0; i < n; ++i) {
    // Model value and its law-parameter derivatives dm[], d2m[][].
    double m, dm[3], pw = 0.0;
    if (pr.law == DampingKind::rayleigh) {
      m = a + b * pr.x[i];
      dm[0] = 1.0;
      dm[1] = pr.x[i];
    } else {
      pw = std::exp(p * pr.log_x[i]);  // x^p
      m = a + b * pw;
      if (pr.law == DampingKind::powerlaw) {
        dm[0] = pw;
        dm[1] = b * pw * pr.log_x[i];
      } else {
        dm[0] = 1.0;
        dm[1] = pw;
        dm[2] = b * pw * pr.log_x[i];
      }
    }
    // Point i's spread; d log sigma_i / d log sigma = 1, so every derivative keeps its form.
    const double sig = pr.noise_scale.empty() ? sigma : sigma * pr.noise_scale[i];
    const double q = kSqrt1_2 / sig;               // ds/dm
    const double es = eta * sig, es2 = es * es;    // eta sigma, eta^2 sigma^2
    const double B = es * kSqrt1_2;                // ds/dlog eta
    const double r = pr.y[i] - m;
    const double s = (es * sig - r) * q;  // (eta sigma^2 - r)/(sqrt2 sigma)
    double le, t;
    log_erfc_with_slope(s, &le, &t);
    sum += log_eta - kLn2 - eta * r + 0.5 * es2 + le;
    if (!want_g && !want_h) continue;

    const double A = B + r * q;  // ds/dlog sigma = eta sigma/sqrt2 + r/(sqrt2 sigma)
    const double l_m = eta + t * q;
    const double l_ls = es2 + t * A;
    const double l_le = 1.0 - eta * r + es2 + t * B;
    for (int j = 0; j < k; ++j) g_law[j] += l_m * dm[j];
    g_ls += l_ls;
    g_le += l_le;
    if (!want_h) continue;

    const double tt = -2.0 * s * t - t * t;  // d^2 log erfc / ds^2
    const double l_mm = tt * q * q;
    const double l_m_ls = tt * q * A - t * q;          // d2s/dm dls = -q
    const double l_m_le = eta + tt * q * B;            // d2P/dm dle = eta; d2s/dm dle = 0
    const double l_ls_ls = 2.0 * es2 + tt * A * A + t * s;  // d2s/dls^2 = s
    const double l_ls_le = 2.0 * es2 + tt * A * B + t * B;  // d2s/dls dle = B
    const double l_le_le = -eta * r + 2.0 * es2 + tt * B * B + t * B;
    for (int j = 0; j < k; ++j) {
      for (int l = 0; l <= j; ++l) h_law[j][l] += l_mm * dm[j] * dm[l];
      h_law_ls[j] += l_m_ls * dm[j];
      h_law_le[j] += l_m_le * dm[j];
    }
    // Second derivatives of the model in (b, p): d2m/db dp = x^p log x, d2m/dp^2 = b x^p log^2 x.
    if (pr.law != DampingKind::rayleigh) {
      const double lx = pr.log_x[i];
      const int ib = pr.law == DampingKind::powerlaw ? 0 : 1, ip = ib + 1;
      h_law[ip][ib] += l_m * pw * lx;
      h_law[ip][ip] += l_m * b * pw * lx * lx;
    }
    h_ls_ls += l_ls_ls;
    h_ls_le += l_ls_le;
    h_le_le += l_le_le;
  }

  if (want_g) {
    gradient->resize(np);
    for (int j = 0; j < k; ++j) (*gradient)[j] = g_law[j];
    (*gradient)[k] = g_ls;
    (*gradient)[k + 1] = g_le;
  }
  if (want_h) {
    EmgMatrix& H = *hessian;
    H.resize(np, np);
    for (int j = 0; j < k; ++j) {
      for (int l = 0; l <= j; ++l) H(j, l) = H(l, j) = h_law[j][l];
      H(j, k) = H(k, j) = h_law_ls[j];
      H(j, k + 1) = H(k + 1, j) = h_law_le[j];
    }
    H(k, k) = h_ls_ls;
    H(k, k + 1) = H(k + 1, k) = h_ls_le;
    H(k + 1, k + 1) = h_le_le;
  }
  return sum;
}

DampingLaw law_from_scaled(const EmgProblem& pr, const EmgVector& theta) {
  DampingLaw law;
  law.kind = pr.law;
  switch (pr.law) {
    case DampingKind::rayleigh:
      law.alpha1 = pr.c_scale * theta[0];
      law.alpha2 = pr.c_scale * theta[1] / pr.lambda_scale;
      law.alpha3 = 1.0;
      break;
    case DampingKind::powerlaw:
      law.alpha1 = 0.0;
      law.alpha3 = theta[1];
      law.alpha2 = pr.c_scale * theta[0] / std::pow(pr.lambda_scale, law.alpha3);
      break;
    case DampingKind::hybrid:
      law.alpha1 = pr.c_scale * theta[0];
      law.alpha3 = theta[2];
      law.alpha2 = pr.c_scale * theta[1] / std::pow(pr.lambda_scale, law.alpha3);
      break;
    case DampingKind::constant_q:
    case DampingKind::relaxation: throw std::invalid_argument(to_string(pr.law) + " is not fitted");
  }
  return law;
}

EmgVector scaled_from_law(const EmgProblem& pr, const DampingLaw& law) {
  EmgVector v(law_param_count(pr.law));
  switch (pr.law) {
    case DampingKind::rayleigh:
      v << law.alpha1 / pr.c_scale, law.alpha2 * pr.lambda_scale / pr.c_scale;
      break;
    case DampingKind::powerlaw:
      v << law.alpha2 * std::pow(pr.lambda_scale, law.alpha3) / pr.c_scale, law.alpha3;
      break;
    case DampingKind::hybrid:
      v << law.alpha1 / pr.c_scale, law.alpha2 * std::pow(pr.lambda_scale, law.alpha3) / pr.c_scale,
          law.alpha3;
      break;
    case DampingKind::constant_q:
    case DampingKind::relaxation: throw std::invalid_argument(to_string(pr.law) + " is not fitted");
  }
  return v;
}

}  // namespace ms
