// Median-periodogram noise estimate (FFTW); see noise_floor.hpp.
#include "analysis/extraction/noise_floor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "synthesis/fft.hpp"

namespace ms {

namespace {

// Hann-windowed periodogram of the recording's last quarter (at least 64 samples): the interior bins
// (0 Hz and Nyquist are chi-square with one degree of freedom), the window energy and the FFT size.
struct TailPeriodogram {
  std::vector<double> power;  // bins 1 .. size/2 - 1
  double window_energy = 0.0;
  std::size_t size = 0;
};

std::optional<TailPeriodogram> tail_periodogram(const std::vector<double>& x) {
  const std::size_t n = std::max<std::size_t>(std::min<std::size_t>(x.size(), 64), x.size() / 4);
  if (n < 16) return std::nullopt;
  TailPeriodogram t;
  t.size = nice_fft_size(n);
  const std::size_t start = x.size() - n;
  RealFft fft(t.size);
  double* in = fft.real();
  std::fill(in, in + t.size, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double w = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (double(i) + 0.5) / double(n));
    in[i] = w * x[start + i];
    t.window_energy += w * w;
  }
  fft.forward();
  const std::complex<double>* out = fft.spectrum();
  t.power.reserve(t.size / 2);
  for (std::size_t k = 1; k < t.size / 2; ++k)
    t.power.push_back(out[k].real() * out[k].real() + out[k].imag() * out[k].imag());
  return t;
}

// Median periodogram value -> white-noise variance (the median of a chi-square(2)/2 is ln 2).
double median_variance(std::vector<double> power, double window_energy) {
  auto mid = power.begin() + std::ptrdiff_t(power.size() / 2);
  std::nth_element(power.begin(), mid, power.end());
  return *mid / (std::numbers::ln2 * window_energy);
}

}  // namespace

double estimate_noise_sigma(const std::vector<double>& x) {
  const auto t = tail_periodogram(x);
  return t ? std::sqrt(median_variance(t->power, t->window_energy)) : 0.0;
}

NoiseProfile estimate_noise_profile(const std::vector<double>& x, double fs, double white_sigma) {
  NoiseProfile p;
  p.white_variance = white_sigma * white_sigma;
  const auto t = tail_periodogram(x);
  if (!t) return p;
  const double bin_hz = fs / double(t->size);
  // Third-octave bands (at least 64 Hz wide); power[i] is bin k = i + 1.
  for (std::size_t k = 1; k < t->size / 2;) {
    const double lo = double(k) * bin_hz, hi = std::max(lo + 64.0, lo * std::cbrt(2.0));
    std::vector<double> band;
    for (; k < t->size / 2 && double(k) * bin_hz < hi; ++k) band.push_back(t->power[k - 1]);
    const double v = median_variance(std::move(band), t->window_energy);
    p.upper_hz.push_back(double(k) * bin_hz);
    p.variance.push_back(v > 4.0 * p.white_variance ? v : p.white_variance);
  }
  return p;
}

double NoiseProfile::variance_at(double freq_hz) const { return max_variance(freq_hz, freq_hz); }

double NoiseProfile::max_variance(double lo_hz, double hi_hz) const {
  double v = white_variance;
  double lower = 0.0;
  for (std::size_t b = 0; b < upper_hz.size(); lower = upper_hz[b], ++b)
    if (upper_hz[b] >= lo_hz && lower <= hi_hz) v = std::max(v, variance[b]);
  return v;
}

double noise_floor_db(double sigma) { return sigma > 0.0 ? 20.0 * std::log10(sigma) : -400.0; }

}  // namespace ms
