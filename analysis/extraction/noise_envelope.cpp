// Short-time low-quantile noise envelope (FFTW); see noise_envelope.hpp.
#include "analysis/extraction/noise_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "synthesis/fft.hpp"

namespace ms {

namespace {

constexpr double kQuantile = 0.2;
// A block counts as louder than the floor only above this ratio: the 20th-percentile estimate over
// a few hundred bins scatters by ~10 %, its running maximum over a 2 s recording by ~30 %, and a dense
// impact's own modes can lift a first frame's quantile by ~3 dB.
constexpr double kMinRatio = 4.0;
constexpr double kLowestHz = 100.0, kHighestShare = 0.45;  // bins used (of fs)

// Samples after which |e^{s n}|^2 < 1e-12: the basis adds nothing to the sums beyond them.
std::size_t basis_span(const DampedComponent& c, std::size_t frames) {
  const double decay = -c.s.real();
  return decay > 0.0 ? std::min(frames, std::size_t(std::ceil(13.8 / decay)) + 1) : frames;
}

// r^T A^-1 r of the 2x2 normal equations: the weighted energy of the fitted component (0 when singular).
double fitted_energy(double a11, double a12, double a22, double r1, double r2) {
  const double det = a11 * a22 - a12 * a12;
  return det > 0.0 ? (a22 * r1 * r1 - 2.0 * a12 * r1 * r2 + a11 * r2 * r2) / det : 0.0;
}

// The end of the run of samples from n (before `end`) over which the envelope's weight stays the same.
std::size_t same_weight_until(const NoiseEnvelope& e, std::size_t n, std::size_t end) {
  const std::size_t k = e.block ? n / e.block : 0;
  return e.block && k < e.variance.size() ? std::min(end, (k + 1) * e.block) : end;
}

}  // namespace

double component_energy(const DampedComponent& c, std::size_t from, std::size_t to) {
  if (to <= from) return 0.0;
  const std::complex<double> b = c.b * std::exp(c.s * double(from));
  const std::size_t n = to - from;
  const std::complex<double> t_abs = weighted_geometric_sum(0, {2.0 * c.s.real(), 0.0}, n);
  const std::complex<double> t_osc = weighted_geometric_sum(0, 2.0 * c.s, n);
  return 0.5 * (std::norm(b) * t_abs.real() + (b * b * t_osc).real());
}

double NoiseEnvelope::weighted_fit_gain(const std::vector<double>& residual, const DampedComponent& c) const {
  // Normal equations of min sum w (y - (p Re u - q Im u))^2, u = e^{s n}, y = residual + Re(b u).
  double a11 = 0.0, a12 = 0.0, a22 = 0.0, r1 = 0.0, r2 = 0.0;
  constexpr std::size_t kAnchor = 1024;  // fresh powers now and then: the recurrence drifts
  const std::size_t span = basis_span(c, residual.size());
  const std::complex<double> step = std::exp(c.s);
  for (std::size_t start = 0; start < span; start += kAnchor) {
    std::complex<double> u = std::exp(c.s * double(start));
    const std::size_t end = std::min(span, start + kAnchor);
    for (std::size_t n = start; n < end;) {
      // The weight is constant over a block: one division per block, not per sample.
      const std::size_t stop = same_weight_until(*this, n, end);
      const double w = 1.0 / at(n);
      for (; n < stop; ++n, u *= step) {
        const double y = residual[n] + (c.b * u).real();
        a11 += w * u.real() * u.real();
        a12 -= w * u.real() * u.imag();
        a22 += w * u.imag() * u.imag();
        r1 += w * y * u.real();
        r2 -= w * y * u.imag();
      }
    }
  }
  return fitted_energy(a11, a12, a22, r1, r2);
}

namespace {

typedef double V4 __attribute__((vector_size(32)));

struct Lanes {  // one group of kLanes components as two 4-wide vectors (GCC/Clang vector extensions)
  static constexpr std::size_t kLanes = 8;
  V4 ur[2]{}, ui[2]{}, sr[2]{}, si[2]{}, br[2]{}, bi[2]{};
  V4 a11[2]{}, a12[2]{}, a22[2]{}, r1[2]{}, r2[2]{};
  static double get(const V4* v, std::size_t l) { return v[l / 4][l % 4]; }
  static void set(V4* v, std::size_t l, double x) { v[l / 4][l % 4] = x; }
};

}  // namespace

std::vector<double> NoiseEnvelope::weighted_fit_gains(const std::vector<double>& residual,
                                                      const std::vector<DampedComponent>& c) const {
  constexpr std::size_t kLanes = Lanes::kLanes, kAnchor = 1024;  // as weighted_fit_gain
  const std::size_t K = c.size();
  std::vector<double> gains(K, 0.0);
  std::vector<std::size_t> span(K), order(K);
  for (std::size_t k = 0; k < K; ++k) {
    span[k] = basis_span(c[k], residual.size());
    order[k] = k;
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return span[a] > span[b]; });
  for (std::size_t g = 0; g < K; g += kLanes) {
    const std::size_t lanes = std::min(kLanes, K - g), len = span[order[g]];
    Lanes v;
    for (std::size_t l = 0; l < lanes; ++l) {
      const DampedComponent& m = c[order[g + l]];
      const std::complex<double> step = std::exp(m.s);
      Lanes::set(v.sr, l, step.real());
      Lanes::set(v.si, l, step.imag());
      Lanes::set(v.br, l, m.b.real());
      Lanes::set(v.bi, l, m.b.imag());
    }
    for (std::size_t start = 0; start < len; start += kAnchor) {
      const std::size_t end = std::min(len, start + kAnchor);
      for (std::size_t n = start; n < end;) {
        // A lane past its span stays at u = 0 and adds nothing, as the single component's sum stops.
        for (std::size_t l = 0; l < lanes; ++l) {
          const std::size_t k = order[g + l];
          const std::complex<double> u = n >= span[k]  ? 0.0
                                         : n == start ? std::exp(c[k].s * double(start))
                                                      : std::complex<double>(Lanes::get(v.ur, l), Lanes::get(v.ui, l));
          Lanes::set(v.ur, l, u.real());
          Lanes::set(v.ui, l, u.imag());
        }
        // Up to the next change: the weight's block, or a lane's span.
        std::size_t stop = same_weight_until(*this, n, end);
        for (std::size_t l = 0; l < lanes; ++l)
          if (span[order[g + l]] > n) stop = std::min(stop, span[order[g + l]]);
        const double w = 1.0 / at(n);
        for (; n < stop; ++n) {
          const double x = residual[n];
          for (int h = 0; h < 2; ++h) {
            const V4 ur = v.ur[h], ui = v.ui[h];
            const V4 y = x + (v.br[h] * ur - v.bi[h] * ui);
            v.a11[h] += w * ur * ur;
            v.a12[h] -= w * ur * ui;
            v.a22[h] += w * ui * ui;
            v.r1[h] += w * y * ur;
            v.r2[h] -= w * y * ui;
            v.ur[h] = ur * v.sr[h] - ui * v.si[h];
            v.ui[h] = ur * v.si[h] + ui * v.sr[h];
          }
        }
      }
    }
    for (std::size_t l = 0; l < lanes; ++l) {
      gains[order[g + l]] = fitted_energy(Lanes::get(v.a11, l), Lanes::get(v.a12, l), Lanes::get(v.a22, l),
                                          Lanes::get(v.r1, l), Lanes::get(v.r2, l));
    }
  }
  return gains;
}

double NoiseEnvelope::variance_seen(double decay_per_sample, std::size_t frames, int power) const {
  if (flat() || block == 0 || frames == 0) return floor_variance;
  const std::complex<double> sigma(-2.0 * std::max(decay_per_sample, 0.0), 0.0);
  // Weight of block [a, a + B): sum_m (a + m)^p q^{a + m} = q^a (T0 a^p + 2 T1 a [p = 2] + T2 [p = 2])
  // with T_j = sum_{m < B} m^j q^m, the same for every block.
  const double T0 = weighted_geometric_sum(0, sigma, block).real();
  const double T1 = weighted_geometric_sum(1, sigma, block).real();
  const double T2 = weighted_geometric_sum(2, sigma, block).real();
  const double step = std::exp(sigma.real() * double(block));
  double qa = 1.0, total = 0.0, weighted = 0.0;
  std::size_t k = 0;
  for (; k < variance.size() && (k + 1) * block <= frames; ++k, qa *= step) {
    const double a = double(k * block);
    const double w = power == 2 ? qa * (T0 * a * a + 2.0 * T1 * a + T2) : qa * T0;
    total += w;
    weighted += w * std::max(variance[k], floor_variance);
  }
  // The rest of the record (the floor, and a partial block if the record ends inside the envelope).
  const std::size_t a = k * block;
  const double whole = weighted_geometric_sum(power, sigma, frames).real();
  const double rest = std::max(0.0, whole - total);
  total = whole;
  weighted += rest * (k < variance.size() && a < frames ? std::max(variance[k], floor_variance) : floor_variance);
  return total > 0.0 ? weighted / total : floor_variance;
}

NoiseEnvelope estimate_noise_envelope(const std::vector<double>& x, double fs, double floor_variance) {
  NoiseEnvelope env;
  env.floor_variance = floor_variance;
  std::size_t window = 256;
  while (double(window) < 0.023 * fs) window *= 2;
  const std::size_t hop = window / 2;
  env.block = window / 16;
  if (x.size() < 2 * window || !(floor_variance > 0.0)) return env;
  const std::size_t frames = 1 + (x.size() - window) / hop;
  const std::size_t k_lo = std::max<std::size_t>(1, std::size_t(std::ceil(kLowestHz * double(window) / fs)));
  const std::size_t k_hi = std::min(window / 2 - 1, std::size_t(kHighestShare * double(window)));
  if (k_hi <= k_lo + 16) return env;
  RealFft fft(window);
  double* in = fft.real();
  const std::complex<double>* out = fft.spectrum();
  std::vector<double> w(window), power(k_hi - k_lo + 1);
  double window_energy = 0.0;
  for (std::size_t i = 0; i < window; ++i) {
    w[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(i) / double(window));
    window_energy += w[i] * w[i];
  }
  const double scale = 1.0 / (-std::log1p(-kQuantile) * window_energy);
  std::vector<double> estimate(frames);
  for (std::size_t f = 0; f < frames; ++f) {
    for (std::size_t i = 0; i < window; ++i) in[i] = w[i] * x[f * hop + i];
    fft.forward();
    for (std::size_t k = k_lo; k <= k_hi; ++k) power[k - k_lo] = out[k].real() * out[k].real() + out[k].imag() * out[k].imag();
    const auto q = power.begin() + std::ptrdiff_t(double(power.size()) * kQuantile);
    std::nth_element(power.begin(), q, power.end());
    estimate[f] = *q * scale;
  }
  // Non-increasing from the right: a frame is at least as noisy as any later one.
  for (std::size_t f = frames - 1; f-- > 0;) estimate[f] = std::max(estimate[f], estimate[f + 1]);
  std::size_t loud = 0;
  while (loud < frames && estimate[loud] > kMinRatio * floor_variance) ++loud;
  // Frame f starts at f * hop: its estimate holds for the hop's blocks.
  for (std::size_t f = 0; f < loud; ++f) env.variance.insert(env.variance.end(), hop / env.block, estimate[f]);
  return env;
}

}  // namespace ms
