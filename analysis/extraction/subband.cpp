// FFT sub-band split (FFTW); see subband.hpp.
#include "analysis/extraction/subband.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ms {


SubbandSplitter::SubbandSplitter(const std::vector<double>& x, double sample_rate_hz,
                                 double noise_sigma, const NoiseProfile* noise)
    : frames_(x.size()), fs_(sample_rate_hz), sigma_(noise_sigma), noise_(noise) {
  // Zero padding of 1/4 keeps the circular wrap of the mask kernels away from the data.
  fft_size_ = nice_fft_size(frames_ + frames_ / 4 + 64);
  bin_hz_ = fs_ / double(fft_size_);
  RealFft fft(fft_size_);
  std::copy(x.begin(), x.end(), fft.real());
  std::fill(fft.real() + frames_, fft.real() + fft_size_, 0.0);
  fft.forward();
  spectrum_.assign(fft.spectrum(), fft.spectrum() + fft_size_ / 2 + 1);
}

SubbandSplitter::~SubbandSplitter() = default;

ComplexInverseFft& SubbandSplitter::plan_for(std::size_t size) {
  auto& p = plans_[size];
  if (!p) p = std::make_unique<ComplexInverseFft>(size);
  return *p;
}

double SubbandSplitter::peak_to_noise(double lo_hz, double hi_hz) const {
  const auto lo = std::size_t(std::max(0.0, std::floor(lo_hz / bin_hz_)));
  const auto hi = std::min(spectrum_.size() - 1, std::size_t(std::max(0.0, std::ceil(hi_hz / bin_hz_))));
  double peak = 0.0;
  for (std::size_t k = lo; k <= hi; ++k) peak = std::max(peak, std::norm(spectrum_[k]));
  const double noise = double(frames_) * variance(lo_hz, hi_hz);
  return noise > 0.0 ? peak / noise : (peak > 0.0 ? 1e300 : 0.0);
}

BandSignal SubbandSplitter::band(double center_hz, double core_hz, double skirt_hz) {
  const long kc = std::lround(center_hz / bin_hz_);
  const double half_core = 0.5 * core_hz, reach = half_core + skirt_hz;
  const long q_max = long(std::ceil(reach / bin_hz_));
  // Decimated rate 10 % above the mask's full width, so nothing aliases.
  ComplexInverseFft& p = plan_for(nice_fft_size(std::size_t(std::ceil(1.1 * 2.0 * reach / bin_hz_)) + 1));
  const std::size_t M = p.size();
  std::complex<double>* buffer = p.data();
  std::fill(buffer, buffer + M, std::complex<double>(0.0, 0.0));
  const long half = long(fft_size_ / 2);
  double mask_energy = 0.0, mask_sum = 0.0;
  for (long q = -q_max; q <= q_max; ++q) {
    const double f = std::abs(double(q) * bin_hz_);
    if (f >= reach) continue;
    const double w = f <= half_core ? 1.0
                                    : 0.5 * (1.0 + std::cos(std::numbers::pi * (f - half_core) / skirt_hz));
    long k = kc + q;
    std::complex<double> v;
    // Bins beyond 0 Hz or Nyquist are the mirror images of the real signal's spectrum.
    if (k < 0) v = std::conj(spectrum_[std::size_t(-k)]);
    else if (k > half) v = std::conj(spectrum_[std::size_t(2 * half - k)]);
    else v = spectrum_[std::size_t(k)];
    const std::size_t slot = std::size_t((q % long(M) + long(M)) % long(M));
    buffer[slot] = w * v;
    mask_energy = std::max(mask_energy, w * w);
    mask_sum += w * w;
  }
  p.execute();
  BandSignal out;
  out.center_hz = double(kc) * bin_hz_;
  out.rate_hz = double(M) * bin_hz_;
  // Samples past the data (plus the kernel's reach) carry only padding.
  const double scale = 2.0 / double(fft_size_);
  const auto usable = std::min<std::size_t>(M, std::size_t(std::ceil(double(frames_) / fs_ * out.rate_hz)));
  out.samples.resize(usable);
  for (std::size_t j = 0; j < usable; ++j) out.samples[j] = scale * buffer[j];
  // White noise: E|S_k|^2 = frames sigma^2; per decimated sample at a flat mask of M bins.
  const double var = variance(center_hz - reach, center_hz + reach);
  out.noise_power = scale * scale * double(frames_) * var * double(M) * mask_energy;
  out.noise_variance = scale * scale * double(frames_) * var * mask_sum;
  // The skirt's kernel has decayed to well under 1e-3 after ~1.5 / skirt_hz.
  out.settle = std::size_t(std::ceil(1.5 / skirt_hz * out.rate_hz));
  return out;
}

}  // namespace ms
