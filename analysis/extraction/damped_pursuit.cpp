// Greedy damped-sinusoid pursuit (FFTW); see damped_pursuit.hpp.
#include "analysis/extraction/damped_pursuit.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "analysis/extraction/subband.hpp"
#include "synthesis/fft.hpp"

namespace ms {
namespace {

using cd = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Spectral neighbours: Lorentzians closer than a few half-widths pull on each other's estimates.
bool overlaps(const DampedComponent& a, const DampedComponent& b) {
  return std::abs(a.s.imag() - b.s.imag()) < 3.0 * (-a.s.real() - b.s.real()) + 1e-3;
}

}  // namespace

std::size_t damped_pursuit(const std::vector<double>& x, double fs, std::vector<DampedComponent>& comps,
                           const PursuitOptions& o) {
  const std::size_t window = std::min(x.size(), std::size_t(o.window_s * fs));
  if (window < 64 || o.noise_variance <= 0.0) return 0;
  // Zero padding to 4x the window: atoms on a grid a quarter of the window's resolution apart.
  const std::size_t size = nice_fft_size(std::max<std::size_t>(4 * window, 8192));
  const double bin_hz = fs / double(size);
  RealFft fft(size);
  double* in = fft.real();
  const std::complex<double>* out = fft.spectrum();
  std::fill(in, in + size, 0.0);
  // Decay envelopes and their energies, computed once.
  std::vector<std::vector<double>> env(o.decays_per_s.size(), std::vector<double>(window));
  std::vector<double> env_energy(o.decays_per_s.size(), 0.0);
  // Noise variance an atom of each decay sees through a room tail (the floor when there is none).
  std::vector<double> env_noise(o.decays_per_s.size(), o.noise_variance);
  const bool tail = o.tail && !o.tail->flat();
  for (std::size_t j = 0; j < env.size(); ++j) {
    double seen = 0.0;
    for (std::size_t n = 0; n < window; ++n) {
      env[j][n] = std::exp(-o.decays_per_s[j] * double(n) / fs);
      env_energy[j] += env[j][n] * env[j][n];
      if (tail) seen += env[j][n] * env[j][n] * std::max(o.noise_variance, o.tail->at(n));
    }
    if (tail) env_noise[j] = seen / env_energy[j];
  }
  const auto k_lo = std::size_t(std::ceil(o.min_freq_hz / bin_hz));
  const auto k_hi = std::min(size / 2, std::size_t(o.max_freq_hz / bin_hz));
  std::vector<double> inv_noise(size / 2 + 1, 1.0 / o.noise_variance);
  if (o.noise)
    for (std::size_t k = 0; k < inv_noise.size(); ++k)
      inv_noise[k] = 1.0 / std::max(o.noise_variance, o.noise->variance_at(double(k) * bin_hz));
  std::vector<double> r = subtract_components(x, comps, x.size());
  RefineOptions ro;
  ro.max_iterations = o.refine_iterations;
  std::vector<double> zeros;
  zeros.reserve(x.size());
  std::size_t added = 0;
  for (int atom = 0; atom < o.max_atoms; ++atom) {
    double best_gain = 0.0, best_inv_noise = 0.0;
    cd best_s, best_b;
    for (std::size_t j = 0; j < env.size(); ++j) {
      for (std::size_t n = 0; n < window; ++n) in[n] = r[n] * env[j][n];
      fft.forward();
      const double inv_env_noise = 1.0 / env_noise[j];  // once per decay, not per bin
      for (std::size_t k = k_lo; k <= k_hi; ++k) {
        const cd y(out[k].real(), -out[k].imag());  // sum r[n] conj(e^{s n})
        // Least-squares energy of Re(b e^{s n}) with b = 2 conj-projection / envelope energy.
        const double inv = std::min(inv_noise[k], inv_env_noise);
        const double gain = 2.0 * std::norm(y) / env_energy[j] * inv;
        if (gain > best_gain) {
          best_gain = gain;
          best_s = cd(-o.decays_per_s[j], kTwoPi * double(k) * bin_hz) / fs;
          best_b = 2.0 * std::conj(y) / env_energy[j];
          best_inv_noise = inv;
        }
      }
    }
    if (best_gain < o.min_gain) break;
    // The new atom and its (fast) neighbours are refit on what the others leave, over the span where
    // they live. Slow neighbours stay fixed: the long narrow-band analysis measured them better.
    const DampedComponent fresh{best_s, best_b};
    std::vector<DampedComponent> local{fresh}, others;
    double slowest = -fresh.s.real();
    for (const auto& c : comps) {
      const bool near = overlaps(c, fresh) && -c.s.real() * fs >= o.min_local_decay_per_s;
      (near ? local : others).push_back(c);
      if (near) slowest = std::min(slowest, -c.s.real());
    }
    const std::size_t span = std::clamp(std::size_t(12.0 / slowest), window, x.size());
    zeros.assign(span, 0.0);  // within the capacity reserved above: no reallocation
    const std::vector<double> minus =
        subtract_components(zeros, std::vector<DampedComponent>(local.begin() + 1, local.end()), span);
    std::vector<double> target(r.begin(), r.begin() + std::ptrdiff_t(span));
    for (std::size_t n = 0; n < span; ++n) target[n] -= minus[n];
    double before = 0.0;
    for (std::size_t n = 0; n < window; ++n) before += r[n] * r[n];
    refine_poles(target, local, ro);
    const std::vector<double> next = subtract_components(target, local, span);
    double after = 0.0;
    for (std::size_t n = 0; n < window; ++n) after += next[n] * next[n];
    // No real gain means the atom explains noise or a fit error the refit cannot absorb.
    if (before - after < 0.25 * o.min_gain / best_inv_noise) break;
    // Beyond the span the old and new neighbours differ by less than e^-12 of their level.
    std::copy(next.begin(), next.end(), r.begin());
    comps = std::move(others);
    comps.insert(comps.end(), local.begin(), local.end());
    ++added;
  }
  return added;
}

}  // namespace ms
