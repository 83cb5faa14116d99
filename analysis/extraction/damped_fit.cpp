// Closed-form Gram matrices and variable-projection Levenberg-Marquardt; see damped_fit.hpp.
#include "analysis/extraction/damped_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace ms {
namespace {

using cd = std::complex<double>;

cd cexpm1(cd z) {  // e^z - 1 without cancellation for small |z|
  const double a = z.real(), b = z.imag(), s = std::sin(0.5 * b);
  return {std::expm1(a) * std::cos(b) - 2.0 * s * s, std::exp(a) * std::sin(b)};
}

// sum_{n<N} n^p, p = 0..16, for the series branch (cached for the last N).
const std::array<double, 17>& power_sums(std::size_t frames) {
  thread_local std::size_t cached = 0;
  thread_local std::array<double, 17> sums{};
  if (cached != frames) {
    std::array<long double, 17> acc{};
    for (std::size_t n = 1; n < frames; ++n) {
      long double v = 1.0L;
      for (int p = 0; p < 17; ++p) {
        acc[std::size_t(p)] += v;
        v *= (long double)n;
      }
    }
    acc[0] += 1.0L;  // n = 0 contributes to p = 0 only
    for (int p = 0; p < 17; ++p) sums[std::size_t(p)] = double(acc[std::size_t(p)]);
    cached = frames;
  }
  return sums;
}

// All three weighted sums at once (shares the exponentials).
std::array<cd, 3> sums012(cd sigma, std::size_t frames) {
  // e^{sigma n} only sees Im(sigma) modulo 2 pi at integer n.
  double im = std::remainder(sigma.imag(), 2.0 * std::numbers::pi);
  sigma = {sigma.real(), im};
  const double N = double(frames);
  std::array<cd, 3> t{};
  if (frames == 0) return t;  // an empty sum (the power-sum series would count n = 0)
  if (std::abs(sigma) * N < 0.05) {
    const auto& P = power_sums(frames);
    for (int p = 0; p < 3; ++p) {
      cd term_scale = 1.0, sum = 0.0;
      for (int j = 0; j + p < 17 && j < 14; ++j) {
        sum += term_scale * P[std::size_t(p + j)];
        term_scale *= sigma / double(j + 1);
      }
      t[std::size_t(p)] = sum;
    }
    return t;
  }
  const cd eps = cexpm1(sigma), mu = cexpm1(N * sigma), E = eps + 1.0, EN = mu + 1.0;
  t[0] = mu / eps;
  t[1] = (N * EN * eps - E * mu) / (eps * eps);
  t[2] = (N * N * EN * eps * eps - mu * E * eps - 2.0 * N * E * EN * eps + 2.0 * mu * E * E) /
         (eps * eps * eps);
  return t;
}

typedef double V4 __attribute__((vector_size(32)));
inline V4 load4(const double* p) { return V4{p[0], p[1], p[2], p[3]}; }
inline void store4(double* p, V4 v) {
  for (int i = 0; i < 4; ++i) p[i] = v[i];
}

struct Projections {
  std::vector<cd> d0, d1;  // sum x[n] e^{s n}, sum n x[n] e^{s n}
};

// The only pass over the samples. Components are processed kLanes at a time (the inner lane loop
// vectorises), longest-lived first, each group up to where its slowest member has decayed by e^-18.
Projections project(const std::vector<double>& x, const std::vector<DampedComponent>& c) {
  constexpr std::size_t kLanes = 8, kAnchor = 1024;  // re-anchor the recurrence to the exact power (drift stays ~1e-13)
  const std::size_t K = c.size();
  Projections out;
  out.d0.resize(K);
  out.d1.resize(K);
  auto reach = [&](std::size_t k) {
    const double decay = -c[k].s.real();
    return decay > 0.0 ? std::min(x.size(), std::size_t(18.0 / decay) + 1) : x.size();
  };
  std::vector<std::size_t> order(K);
  for (std::size_t k = 0; k < K; ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return reach(a) > reach(b); });
  for (std::size_t g = 0; g < K; g += kLanes) {
    const std::size_t lanes = std::min(kLanes, K - g), len = reach(order[g]);
    alignas(64) double pr[kLanes] = {}, pi[kLanes] = {}, sr[kLanes] = {}, si[kLanes] = {};
    alignas(64) double a0r[kLanes] = {}, a0i[kLanes] = {}, a1r[kLanes] = {}, a1i[kLanes] = {};
    for (std::size_t l = 0; l < lanes; ++l) {
      const cd step = std::exp(c[order[g + l]].s);
      sr[l] = step.real();
      si[l] = step.imag();
    }
    for (std::size_t start = 0; start < len; start += kAnchor) {
      for (std::size_t l = 0; l < lanes; ++l) {
        const cd p0 = std::exp(c[order[g + l]].s * double(start));
        pr[l] = p0.real();
        pi[l] = p0.imag();
      }
      const std::size_t end = std::min(len, start + kAnchor);
      // Two 4-wide vectors (GCC/Clang vector extensions): the lane loop as explicit SIMD.
      V4 r0 = load4(pr), r1 = load4(pr + 4), i0 = load4(pi), i1 = load4(pi + 4);
      const V4 cr0 = load4(sr), cr1 = load4(sr + 4), ci0 = load4(si), ci1 = load4(si + 4);
      V4 s0r0 = load4(a0r), s0r1 = load4(a0r + 4), s0i0 = load4(a0i), s0i1 = load4(a0i + 4);
      V4 s1r0 = load4(a1r), s1r1 = load4(a1r + 4), s1i0 = load4(a1i), s1i1 = load4(a1i + 4);
      for (std::size_t n = start; n < end; ++n) {
        const double v = x[n], vn = v * double(n);
        s0r0 += v * r0; s0r1 += v * r1; s0i0 += v * i0; s0i1 += v * i1;
        s1r0 += vn * r0; s1r1 += vn * r1; s1i0 += vn * i0; s1i1 += vn * i1;
        const V4 n0 = r0 * cr0 - i0 * ci0, n1 = r1 * cr1 - i1 * ci1;
        i0 = r0 * ci0 + i0 * cr0;
        i1 = r1 * ci1 + i1 * cr1;
        r0 = n0;
        r1 = n1;
      }
      store4(a0r, s0r0); store4(a0r + 4, s0r1); store4(a0i, s0i0); store4(a0i + 4, s0i1);
      store4(a1r, s1r0); store4(a1r + 4, s1r1); store4(a1i, s1i0); store4(a1i + 4, s1i1);
    }
    for (std::size_t l = 0; l < lanes; ++l) {
      out.d0[order[g + l]] = {a0r[l], a0i[l]};
      out.d1[order[g + l]] = {a1r[l], a1i[l]};
    }
  }
  return out;
}

// Gram of the amplitude columns Re(e^{s n}), Re(i e^{s n}) for all components.
void amplitude_gram_into(const std::vector<DampedComponent>& c, std::size_t frames, Eigen::MatrixXd& G) {
  const std::size_t K = c.size();
  G.resize(Eigen::Index(2 * K), Eigen::Index(2 * K));
  const std::array<cd, 2> alpha{cd(1, 0), cd(0, 1)};
  for (std::size_t j = 0; j < K; ++j)
    for (std::size_t k = j; k < K; ++k) {
      const cd tp = sums012(c[j].s + c[k].s, frames)[0];
      const cd tm = sums012(c[j].s + std::conj(c[k].s), frames)[0];
      for (std::size_t u = 0; u < 2; ++u)
        for (std::size_t v = 0; v < 2; ++v) {
          const double g = 0.5 * (alpha[u] * alpha[v] * tp + alpha[u] * std::conj(alpha[v]) * tm).real();
          G(Eigen::Index(2 * j + u), Eigen::Index(2 * k + v)) = g;
          G(Eigen::Index(2 * k + v), Eigen::Index(2 * j + u)) = g;
        }
    }
}

double energy(const std::vector<double>& x) {
  double e = 0.0;
  for (double v : x) e += v * v;
  return e;
}

// Solves G x = r for a Gram matrix G (symmetric, positive semi-definite) by LDLT in G's own storage,
// which it overwrites: at the hundreds of columns a room recording's fit has, G is megabytes, and a
// fresh copy per solve cost more in page faults than the factorisation. (A blocked Cholesky is ~3x
// faster here but rounds differently; the fit's accept/reject steps and audibility bars are tuned on
// these solutions, so a change of solver is a change of results, to be re-validated as one.)
Eigen::VectorXd ldlt_solve_in_place(Eigen::MatrixXd& G, const Eigen::VectorXd& r) {
  const Eigen::LDLT<Eigen::Ref<Eigen::MatrixXd>> ldlt(G);
  return ldlt.solve(r);
}

// Solves the amplitudes for fixed poles from precomputed projections; returns residual energy.
// G is the caller's workspace: at hundreds of components the Gram is megabytes, and fresh pages cost
// more than its arithmetic.
double solve_amplitudes(double x_energy, const Projections& pr, std::vector<DampedComponent>& c,
                        std::size_t frames, Eigen::MatrixXd& G) {
  const std::size_t K = c.size();
  if (K == 0) return x_energy;
  Eigen::VectorXd r(2 * K);
  for (std::size_t k = 0; k < K; ++k) {
    r(Eigen::Index(2 * k)) = pr.d0[k].real();        // <x, Re(e^{sn})>
    r(Eigen::Index(2 * k + 1)) = -pr.d0[k].imag();   // <x, Re(i e^{sn})>
  }
  // A whisper of ridge keeps coincident poles solvable.
  auto build = [&] {
    amplitude_gram_into(c, frames, G);
    G.diagonal().array() += 1e-12 * G.diagonal().maxCoeff();
  };
  build();
  Eigen::VectorXd beta = ldlt_solve_in_place(G, r);
  // Nearly coincident poles can defeat LDLT; rank-revealing QR copes.
  if (!beta.allFinite()) {
    build();
    beta = G.colPivHouseholderQr().solve(r);
  }
  if (!beta.allFinite()) return std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < K; ++k) c[k].b = {beta(Eigen::Index(2 * k)), beta(Eigen::Index(2 * k + 1))};
  return std::max(0.0, x_energy - beta.dot(r));
}

}  // namespace

cd weighted_geometric_sum(int power, cd sigma, std::size_t frames) {
  return sums012(sigma, frames)[std::size_t(std::clamp(power, 0, 2))];
}

std::vector<double> subtract_components(const std::vector<double>& x, const std::vector<DampedComponent>& c,
                                        std::size_t frames) {
  constexpr std::size_t kLanes = 8, kAnchor = 1024;
  std::vector<double> out(x.begin(), x.begin() + std::ptrdiff_t(std::min(frames, x.size())));
  for (std::size_t g = 0; g < c.size(); g += kLanes) {
    const std::size_t lanes = std::min(kLanes, c.size() - g);
    alignas(64) double pr[kLanes] = {}, pi[kLanes] = {}, sr[kLanes] = {}, si[kLanes] = {};
    for (std::size_t l = 0; l < lanes; ++l) {
      const cd step = std::exp(c[g + l].s);
      sr[l] = step.real();
      si[l] = step.imag();
    }
    for (std::size_t start = 0; start < out.size(); start += kAnchor) {
      for (std::size_t l = 0; l < lanes; ++l) {
        const cd p0 = c[g + l].b * std::exp(c[g + l].s * double(start));
        pr[l] = p0.real();
        pi[l] = p0.imag();
      }
      const std::size_t end = std::min(out.size(), start + kAnchor);
      for (std::size_t n = start; n < end; ++n) {
        double sum = 0.0;
        for (std::size_t l = 0; l < kLanes; ++l) {
          sum += pr[l];
          const double nr = pr[l] * sr[l] - pi[l] * si[l];
          pi[l] = pr[l] * si[l] + pi[l] * sr[l];
          pr[l] = nr;
        }
        out[n] -= sum;
      }
    }
  }
  return out;
}

double fit_amplitudes(const std::vector<double>& x, std::vector<DampedComponent>& components) {
  Eigen::MatrixXd gram;
  return solve_amplitudes(energy(x), project(x, components), components, x.size(), gram);
}

namespace {

void pole_gram_into(const std::vector<DampedComponent>& c, std::size_t frames, Eigen::MatrixXd& A) {
  const std::size_t K = c.size();
  A.resize(Eigen::Index(4 * K), Eigen::Index(4 * K));
  std::vector<std::array<cd, 4>> alpha(K);
  for (std::size_t k = 0; k < K; ++k) alpha[k] = {cd(1, 0), cd(0, 1), c[k].b, cd(0, 1) * c[k].b};
  constexpr std::array<int, 4> pw{0, 0, 1, 1};
  for (std::size_t j = 0; j < K; ++j)
    for (std::size_t k = j; k < K; ++k) {
      const auto tp = sums012(c[j].s + c[k].s, frames);
      const auto tm = sums012(c[j].s + std::conj(c[k].s), frames);
      for (std::size_t u = 0; u < 4; ++u)
        for (std::size_t v = 0; v < 4; ++v) {
          const std::size_t q = std::size_t(pw[u] + pw[v]);
          const double val =
              0.5 * (alpha[j][u] * alpha[k][v] * tp[q] + alpha[j][u] * std::conj(alpha[k][v]) * tm[q]).real();
          A(Eigen::Index(4 * j + u), Eigen::Index(4 * k + v)) = val;
          A(Eigen::Index(4 * k + v), Eigen::Index(4 * j + u)) = val;
        }
    }
}

}  // namespace

Eigen::MatrixXd pole_gram(const std::vector<DampedComponent>& c, std::size_t frames) {
  Eigen::MatrixXd A;
  pole_gram_into(c, frames, A);
  return A;
}

double refine_poles(const std::vector<double>& x, std::vector<DampedComponent>& c,
                    const RefineOptions& options) {
  const std::size_t K = c.size(), N = x.size();
  const double xe = energy(x);
  if (K == 0) return xe;
  // Workspaces kept over the iterations (see solve_amplitudes).
  Eigen::MatrixXd A, L, amplitude_workspace;
  Projections pr = project(x, c);
  double cost = solve_amplitudes(xe, pr, c, N, amplitude_workspace);
  double lambda = 1e-3;
  for (int iter = 0; iter < options.max_iterations; ++iter) {
    // Full Gram of the 4K columns Re(alpha n^p e^{s n}) and the gradient J^T (x - model).
    const Eigen::Index P = Eigen::Index(4 * K);
    pole_gram_into(c, N, A);
    Eigen::VectorXd g(P);
    std::vector<std::array<cd, 4>> alpha(K);
    for (std::size_t k = 0; k < K; ++k) alpha[k] = {cd(1, 0), cd(0, 1), c[k].b, cd(0, 1) * c[k].b};
    constexpr std::array<int, 4> pw{0, 0, 1, 1};
    for (std::size_t k = 0; k < K; ++k)
      for (std::size_t u = 0; u < 4; ++u) {
        const cd d = pw[u] == 0 ? pr.d0[k] : pr.d1[k];
        g(Eigen::Index(4 * k + u)) = (alpha[k][u] * d).real();
      }
    Eigen::VectorXd beta(P);  // model = sum of the amplitude columns times (Re b, Im b)
    beta.setZero();
    for (std::size_t k = 0; k < K; ++k) {
      beta(Eigen::Index(4 * k)) = c[k].b.real();
      beta(Eigen::Index(4 * k + 1)) = c[k].b.imag();
    }
    g -= A * beta;
    bool accepted = false;
    for (int attempt = 0; attempt < 8 && !accepted; ++attempt) {
      L = A;
      L.diagonal() += lambda * A.diagonal();
      const Eigen::VectorXd delta = ldlt_solve_in_place(L, g);
      std::vector<DampedComponent> trial = c;
      for (std::size_t k = 0; k < K; ++k) {
        trial[k].s += cd(delta(Eigen::Index(4 * k + 2)), delta(Eigen::Index(4 * k + 3)));
        // Growing components are not modes (and would overflow the closed forms): keep d >= 0.
        trial[k].s = {std::min(trial[k].s.real(), 0.0), trial[k].s.imag()};
      }
      Projections tp = project(x, trial);
      const double tcost = solve_amplitudes(xe, tp, trial, N, amplitude_workspace);
      if (std::isfinite(tcost) && tcost < cost) {
        const double gain = (cost - tcost) / std::max(cost, 1e-300);
        c = std::move(trial);
        pr = std::move(tp);
        cost = tcost;
        lambda = std::max(lambda / 4.0, 1e-9);
        accepted = true;
        if (gain < options.relative_tolerance) return cost;
      } else {
        lambda *= 8.0;
      }
    }
    if (!accepted) break;
  }
  return cost;
}

}  // namespace ms
