// The short-time Fourier transform the residual is stated on (patent US 9,401,684 Sec. 6): a periodic
// Hann window of fft_size samples, no zero padding, frames centred on the multiples of hop (frame m
// holds samples [m hop - N/2, m hop + N/2), zero outside the signal), so every sample of a signal is
// covered by N / hop frames and the least-squares inverse (Griffin & Lim 1984, Eq. 6) is exact on a
// consistent spectrogram. Power is FFTW's unnormalised |X_m[k]|^2 in digital full-scale units.
// The closed-form power of one damped sinusoid on the same grid guides the residual's transfer.
#pragma once
#include <complex>
#include <cstddef>
#include <vector>

#include "synthesis/fft.hpp"
#include "synthesis/modal_model.hpp"

namespace ms {

struct StftGrid {
  std::size_t fft_size = 1024;  // N: window length and transform size (23.2 ms at 44.1 kHz)
  std::size_t hop = 256;        // N/4: 75 % overlap
  std::size_t bins() const { return fft_size / 2 + 1; }
  // Frames covering `samples` samples: centres 0, hop, ... up to the last sample.
  std::size_t frames_for(std::size_t samples) const { return samples / hop + 1; }
};

// Forward and least-squares inverse transforms of one grid, with the FFTW plan and buffers made once;
// after the first call for a signal length neither allocates.
class Stft {
 public:
  // Throws std::invalid_argument unless fft_size is even and >= 16 and 1 <= hop <= fft_size / 2.
  explicit Stft(const StftGrid& grid);

  const StftGrid& grid() const { return grid_; }
  const std::vector<double>& window() const { return window_; }

  // spectra: frames_for(samples) x bins, frame-major.
  void forward(const double* x, std::size_t samples, std::complex<double>* spectra);
  // x = sum_m w y_m / sum_m w^2 (y_m the inverse transform of frame m), the signal whose STFT is
  // nearest `spectra` in the least-squares sense; frames must equal frames_for(samples).
  void inverse(const std::complex<double>* spectra, std::size_t samples, double* x);
  // Makes inverse()'s overlap normalisation for this signal length now (it is otherwise made, once,
  // by the first inverse() of that length), so that a loop of inverses allocates nothing.
  void prepare_inverse(std::size_t samples);

  // Power spectrogram of x: frames_for(x.size()) x bins, frame-major.
  std::vector<double> power(const std::vector<float>& x);

 private:
  StftGrid grid_;
  std::vector<double> window_;
  RealFft fft_;
  std::vector<double> window_square_sum_;  // per sample, for the signal length last inverted
};

// The power |X_m[k]|^2 of x[n] = amp e^{-d n/fs} sin(2 pi f n/fs + phase) (n >= 0, 0 before) on
// `grid`, in closed form: the Hann window is three complex exponentials and each frame's sum a
// geometric series; frames after the strike's differ only by a factor, so a pixel costs two complex
// products and no transform. Writes the frames
// [frame_begin, frame_end) x bins [bin_begin, bin_end) row by row into out.
void damped_sine_power(const Mode& mode, double sample_rate_hz, const StftGrid& grid, std::size_t frame_begin,
                       std::size_t frame_end, std::size_t bin_begin, std::size_t bin_end, double* out);

}  // namespace ms
