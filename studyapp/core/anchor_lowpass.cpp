// lowpass_anchor: one real FFT forward, a gain per bin, one back (FFTW, double precision).
#include "studyapp/core/anchor_lowpass.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "synthesis/fft.hpp"

namespace ms {

std::vector<float> lowpass_anchor(const std::vector<float>& samples, double fs, double cutoff_hz) {
  if (samples.empty()) return {};
  // Padding keeps the filter's (short) time response from wrapping the tail onto the attack.
  const std::size_t n = nice_fft_size(samples.size() + samples.size() / 8 + 1024);
  RealFft fft(n, RealFft::Directions::forward_and_backward);
  double* buf = fft.real();
  std::complex<double>* spec = fft.spectrum();
  std::fill(buf, buf + n, 0.0);
  std::copy(samples.begin(), samples.end(), buf);
  fft.forward();
  const double width_hz = 0.05 * cutoff_hz, lo = cutoff_hz - width_hz / 2, hi = cutoff_hz + width_hz / 2;
  for (std::size_t k = 0; k <= n / 2; ++k) {
    const double f = double(k) * fs / double(n);
    double g = 1.0;
    if (f >= hi) g = 0.0;
    else if (f > lo) g = 0.5 * (1.0 + std::cos(std::numbers::pi * (f - lo) / width_hz));
    g /= double(n);  // FFTW's inverse is unnormalised
    spec[k] *= g;
  }
  fft.backward();
  std::vector<float> out(samples.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = float(buf[i]);
  return out;
}

}  // namespace ms
