// The residual's STFT grid, its transforms and the closed-form power of a damped sinusoid; see
// residual_stft.hpp.
#include "synthesis/residual_stft.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ms {

namespace {

const StftGrid& checked(const StftGrid& g) {
  if (g.fft_size < 16 || g.fft_size % 2 != 0 || g.hop < 1 || g.hop > g.fft_size / 2)
    throw std::invalid_argument("STFT grid: fft_size must be even and >= 16, hop in [1, fft_size/2]");
  return g;
}

// First sample of frame m (negative for the frames that start before the signal).
long long frame_start(const StftGrid& g, std::size_t m) {
  return (long long)(m * g.hop) - (long long)(g.fft_size / 2);
}

}  // namespace

Stft::Stft(const StftGrid& grid)
    : grid_(checked(grid)),
      window_(grid.fft_size),
      fft_(grid.fft_size, RealFft::Directions::forward_and_backward) {
  for (std::size_t j = 0; j < grid_.fft_size; ++j)
    window_[j] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(j) / double(grid_.fft_size));
}

void Stft::forward(const double* x, std::size_t samples, std::complex<double>* spectra) {
  const std::size_t n = grid_.fft_size, bins = grid_.bins(), frames = grid_.frames_for(samples);
  for (std::size_t m = 0; m < frames; ++m) {
    const long long s = frame_start(grid_, m);
    double* in = fft_.real();
    if (s >= 0 && s + (long long)n <= (long long)samples) {
      for (std::size_t j = 0; j < n; ++j) in[j] = window_[j] * x[s + (long long)j];
    } else {
      for (std::size_t j = 0; j < n; ++j) {
        const long long i = s + (long long)j;
        in[j] = i >= 0 && i < (long long)samples ? window_[j] * x[i] : 0.0;
      }
    }
    fft_.forward();
    std::copy(fft_.spectrum(), fft_.spectrum() + bins, spectra + m * bins);
  }
}

void Stft::prepare_inverse(std::size_t samples) {
  if (window_square_sum_.size() == samples) return;
  window_square_sum_.assign(samples, 0.0);
  for (std::size_t m = 0; m < grid_.frames_for(samples); ++m) {
    const long long s = frame_start(grid_, m);
    for (std::size_t j = 0; j < grid_.fft_size; ++j)
      if (const long long i = s + (long long)j; i >= 0 && i < (long long)samples)
        window_square_sum_[i] += window_[j] * window_[j];
  }
}

void Stft::inverse(const std::complex<double>* spectra, std::size_t samples, double* x) {
  const std::size_t n = grid_.fft_size, bins = grid_.bins(), frames = grid_.frames_for(samples);
  prepare_inverse(samples);
  std::fill(x, x + samples, 0.0);
  const double scale = 1.0 / double(n);  // FFTW's c2r returns n times the inverse DFT
  for (std::size_t m = 0; m < frames; ++m) {
    std::copy(spectra + m * bins, spectra + (m + 1) * bins, fft_.spectrum());
    fft_.backward();
    const long long s = frame_start(grid_, m);
    const double* y = fft_.real();
    if (s >= 0 && s + (long long)n <= (long long)samples) {
      double* out = x + s;
      for (std::size_t j = 0; j < n; ++j) out[j] += window_[j] * y[j] * scale;
    } else {
      for (std::size_t j = 0; j < n; ++j)
        if (const long long i = s + (long long)j; i >= 0 && i < (long long)samples)
          x[i] += window_[j] * y[j] * scale;
    }
  }
  for (std::size_t i = 0; i < samples; ++i)
    x[i] = window_square_sum_[i] > 1e-12 ? x[i] / window_square_sum_[i] : 0.0;
}

std::vector<double> Stft::power(const std::vector<float>& x) {
  const std::size_t bins = grid_.bins(), frames = grid_.frames_for(x.size());
  std::vector<double> signal(x.begin(), x.end());
  std::vector<std::complex<double>> spectra(frames * bins);
  forward(signal.data(), signal.size(), spectra.data());
  std::vector<double> p(frames * bins);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = std::norm(spectra[i]);
  return p;
}

void damped_sine_power(const Mode& mode, double fs, const StftGrid& grid, std::size_t frame_begin,
                       std::size_t frame_end, std::size_t bin_begin, std::size_t bin_end, double* out) {
  using C = std::complex<double>;
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  const double n = double(grid.fft_size);
  // x[n] = sum_c coef_c pole_c^n: sin(theta n + phase) = (e^{i(theta n + phase)} - e^{-i(...)}) / 2i.
  const double delta = mode.decay_per_s / fs, theta = kTwoPi * mode.freq_hz / fs;
  const C log_pole[2] = {C(-delta, theta), C(-delta, -theta)};
  const C coef[2] = {mode.amp * std::polar(1.0, mode.phase_rad) / C(0.0, 2.0),
                     -mode.amp * std::polar(1.0, -mode.phase_rad) / C(0.0, 2.0)};
  // Periodic Hann: w_j = sum_q w_q e^{i 2 pi q j / N}.
  constexpr int kQ[3] = {-1, 0, 1};
  constexpr double kWq[3] = {-0.25, 0.5, -0.25};
  const C pole[2] = {std::exp(log_pole[0]), std::exp(log_pole[1])};
  // pole^s sum_{j=j0}^{N-1} r^j with r = pole e^{i turn}, turn = 2 pi (q - k) / N: the frame's window
  // sum from its first sample at or after the strike, s + j0 >= 0 (so nothing overflows however fast
  // the decay); r^N = pole^N e^{i turn N} and turn N is a whole number of turns.
  const auto frame_sum = [&](int c, double turn, long long s, long long j0) {
    const C r = pole[c] * std::polar(1.0, turn);
    const C first = std::exp(double(s + j0) * log_pole[c]) * std::polar(1.0, turn * double(j0));
    if (std::abs(1.0 - r) <= 1e-12) return first * (n - double(j0));  // undamped and on the bin
    return (first - std::exp((double(s) + n) * log_pole[c])) / (1.0 - r);
  };
  // Frames wholly after the strike (j0 = 0) differ only by the factor pole^s: their window sums per
  // bin are computed once.
  const std::size_t width = bin_end - bin_begin;
  std::vector<C> whole(2 * width);
  for (std::size_t k = bin_begin; k < bin_end; ++k)
    for (int c = 0; c < 2; ++c) {
      C sum(0.0, 0.0);
      for (int qi = 0; qi < 3; ++qi) sum += kWq[qi] * frame_sum(c, kTwoPi * double(kQ[qi] - (long long)k) / n, 0, 0);
      whole[2 * (k - bin_begin) + c] = sum;
    }
  for (std::size_t m = frame_begin; m < frame_end; ++m) {
    const long long s = frame_start(grid, m);
    const long long j0 = std::max(0LL, -s);  // first window sample at or after the strike
    double* row = out + (m - frame_begin) * width;
    C start[2] = {};  // coef pole^s, for the frames after the strike
    if (j0 == 0)
      for (int c = 0; c < 2; ++c) start[c] = coef[c] * std::exp(double(s) * log_pole[c]);
    for (std::size_t k = bin_begin; k < bin_end; ++k) {
      C x(0.0, 0.0);
      if (j0 == 0) {
        x = start[0] * whole[2 * (k - bin_begin)] + start[1] * whole[2 * (k - bin_begin) + 1];
      } else {
        for (int qi = 0; qi < 3; ++qi)
          for (int c = 0; c < 2; ++c)
            x += kWq[qi] * coef[c] * frame_sum(c, kTwoPi * double(kQ[qi] - (long long)k) / n, s, j0);
      }
      row[k - bin_begin] = std::norm(x);
    }
  }
}

}  // namespace ms
