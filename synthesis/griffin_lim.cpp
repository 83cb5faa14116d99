// Fast Griffin-Lim; see griffin_lim.hpp.
#include "synthesis/griffin_lim.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

namespace ms {

namespace {

using C = std::complex<double>;

// Uniform in [0, 1) from the generator's top 53 bits: the same on every standard library, unlike
// std::uniform_real_distribution.
double unit_uniform(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

// c <- |S| c / |c|, the nearest spectrogram with the target magnitude.
void impose_magnitude(const std::vector<double>& magnitude, std::vector<C>& c) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double a = std::sqrt(std::norm(c[i]));  // not std::abs: hypot's care for overflow costs here
    c[i] = a > 1e-300 ? c[i] * (magnitude[i] / a) : C(magnitude[i], 0.0);
  }
}

double convergence_db(const std::vector<C>& spectra, const std::vector<double>& magnitude) {
  double error = 0.0, target = 0.0;
  for (std::size_t i = 0; i < spectra.size(); ++i) {
    const double e = std::abs(spectra[i]) - magnitude[i];
    error += e * e;
    target += magnitude[i] * magnitude[i];
  }
  if (target <= 0.0) return -std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(std::max(error, 1e-300) / target);
}

std::vector<double> magnitudes(const std::vector<float>& power, const StftGrid& grid, std::size_t samples) {
  if (power.size() != grid.frames_for(samples) * grid.bins())
    throw std::invalid_argument("griffin_lim: the spectrogram holds " + std::to_string(power.size()) +
                                " values, frames_for(samples) x bins = " +
                                std::to_string(grid.frames_for(samples) * grid.bins()));
  std::vector<double> s(power.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!(power[i] >= 0.0f) || !std::isfinite(power[i]))
      throw std::invalid_argument("griffin_lim: a power is negative or not finite");
    s[i] = std::sqrt(double(power[i]));
  }
  return s;
}

}  // namespace

GriffinLimResult griffin_lim(const std::vector<float>& power, const StftGrid& grid, std::size_t samples,
                             const GriffinLimOptions& options) {
  const std::vector<double> magnitude = magnitudes(power, grid, samples);
  Stft stft(grid);
  stft.prepare_inverse(samples);
  std::vector<C> c(magnitude.size()), t(magnitude.size()), t_previous(magnitude.size());
  std::vector<double> x(samples);
  std::mt19937_64 rng(options.seed);
  for (std::size_t i = 0; i < c.size(); ++i)
    c[i] = std::polar(magnitude[i], 2.0 * std::numbers::pi * unit_uniform(rng));
  for (std::size_t n = 0; n < options.iterations; ++n) {
    impose_magnitude(magnitude, c);
    stft.inverse(c.data(), samples, x.data());
    stft.forward(x.data(), samples, t.data());
    const double alpha = n == 0 ? 0.0 : options.momentum;  // no previous t before the first step
    for (std::size_t i = 0; i < c.size(); ++i) {
      c[i] = t[i] + alpha * (t[i] - t_previous[i]);
      t_previous[i] = t[i];
    }
  }
  impose_magnitude(magnitude, c);
  stft.inverse(c.data(), samples, x.data());
  stft.forward(x.data(), samples, t.data());
  GriffinLimResult out;
  out.samples.assign(x.begin(), x.end());
  out.spectral_convergence_db = convergence_db(t, magnitude);
  return out;
}

double spectral_convergence_db(const std::vector<float>& x, const std::vector<float>& power, const StftGrid& grid) {
  const std::vector<double> magnitude = magnitudes(power, grid, x.size());
  Stft stft(grid);
  const std::vector<double> signal(x.begin(), x.end());
  std::vector<C> spectra(magnitude.size());
  stft.forward(signal.data(), signal.size(), spectra.data());
  return convergence_db(spectra, magnitude);
}

}  // namespace ms
