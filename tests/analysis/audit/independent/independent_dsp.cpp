#include "independent_dsp.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace ms::indep {

namespace {

// The audio-cookbook second-order low/high-pass: the analog section s^2 + s/Q + 1 mapped by the
// bilinear transform with the cutoff prewarped, so the digital -3 dB point sits at cutoff_hz.
Biquad section(double cutoff_hz, double q, double fs, bool highpass) {
  const double w0 = 2.0 * std::numbers::pi * cutoff_hz / fs;
  const double c = std::cos(w0), alpha = std::sin(w0) / (2.0 * q);
  const double a0 = 1.0 + alpha;
  Biquad b;
  if (highpass) {
    b.b0 = 0.5 * (1.0 + c) / a0;
    b.b1 = -(1.0 + c) / a0;
  } else {
    b.b0 = 0.5 * (1.0 - c) / a0;
    b.b1 = (1.0 - c) / a0;
  }
  b.b2 = b.b0;
  b.a1 = -2.0 * c / a0;
  b.a2 = (1.0 - alpha) / a0;
  return b;
}

Butterworth4 butterworth4(double cutoff_hz, double fs, bool highpass) {
  Butterworth4 f;
  f.sections[0] = section(cutoff_hz, 1.0 / (2.0 * std::cos(std::numbers::pi / 8.0)), fs, highpass);
  f.sections[1] = section(cutoff_hz, 1.0 / (2.0 * std::cos(3.0 * std::numbers::pi / 8.0)), fs, highpass);
  return f;
}

}  // namespace

Butterworth4 butterworth4_lowpass(double cutoff_hz, double fs) { return butterworth4(cutoff_hz, fs, false); }
Butterworth4 butterworth4_highpass(double cutoff_hz, double fs) { return butterworth4(cutoff_hz, fs, true); }

std::vector<double> convolve_fft(const std::vector<double>& x, const std::vector<double>& h, std::size_t out_frames) {
  std::vector<double> y(out_frames, 0.0);
  if (x.empty() || h.empty()) return y;
  const std::size_t full = x.size() + h.size() - 1;
  std::size_t n = 1;
  while (n < full) n *= 2;
  const std::size_t bins = n / 2 + 1;
  double* xt = fftw_alloc_real(n);
  double* ht = fftw_alloc_real(n);
  fftw_complex* xf = fftw_alloc_complex(bins);
  fftw_complex* hf = fftw_alloc_complex(bins);
  const fftw_plan fx = fftw_plan_dft_r2c_1d(int(n), xt, xf, FFTW_ESTIMATE);
  const fftw_plan fh = fftw_plan_dft_r2c_1d(int(n), ht, hf, FFTW_ESTIMATE);
  const fftw_plan inv = fftw_plan_dft_c2r_1d(int(n), xf, xt, FFTW_ESTIMATE);
  std::fill(xt, xt + n, 0.0);
  std::fill(ht, ht + n, 0.0);
  std::copy(x.begin(), x.end(), xt);
  std::copy(h.begin(), h.end(), ht);
  fftw_execute(fx);
  fftw_execute(fh);
  for (std::size_t k = 0; k < bins; ++k) {
    const std::complex<double> p = std::complex<double>(xf[k][0], xf[k][1]) * std::complex<double>(hf[k][0], hf[k][1]);
    xf[k][0] = p.real();
    xf[k][1] = p.imag();
  }
  fftw_execute(inv);  // unnormalised: divide by n
  for (std::size_t i = 0; i < out_frames && i < full; ++i) y[i] = xt[i] / double(n);
  fftw_destroy_plan(fx);
  fftw_destroy_plan(fh);
  fftw_destroy_plan(inv);
  fftw_free(xt);
  fftw_free(ht);
  fftw_free(xf);
  fftw_free(hf);
  return y;
}

std::vector<double> tilted_noise(std::size_t frames, double rms, double corner_hz, double fs, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  const double pole = std::exp(-2.0 * std::numbers::pi * corner_hz / fs);
  std::vector<double> y(frames);
  double low = 0.0;
  for (std::size_t i = 0; i < frames + 2048; ++i) {  // 2048 samples to settle the low-pass
    const double w = normal(rng);
    low = pole * low + (1.0 - pole) * w;
    if (i >= 2048) y[i - 2048] = 0.3 * w + 6.0 * low;
  }
  const double r = rms_of(y, 0, y.size());
  if (r > 0.0)
    for (double& v : y) v *= rms / r;
  return y;
}

double rms_of(const std::vector<double>& x, std::size_t begin, std::size_t end) {
  end = std::min(end, x.size());
  if (end <= begin) return 0.0;
  double e = 0.0;
  for (std::size_t i = begin; i < end; ++i) e += x[i] * x[i];
  return std::sqrt(e / double(end - begin));
}

}  // namespace ms::indep
