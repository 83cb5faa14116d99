// Signal pieces of the independent hidden-effect generator, written apart from synthesis/ and analysis/
// so that the audit is proven on physics it does not share: Butterworth biquads, white and tilted
// Gaussian noise, and linear convolution by FFT (FFTW directly, double precision).
#pragma once
#include <cstddef>
#include <random>
#include <vector>

namespace ms::indep {

// One second-order section, transposed direct form II, double precision.
struct Biquad {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0, a1 = 0.0, a2 = 0.0;  // a0 normalised to 1
  double s1 = 0.0, s2 = 0.0;
  double step(double x) {
    const double y = b0 * x + s1;
    s1 = b1 * x - a1 * y + s2;
    s2 = b2 * x - a2 * y;
    return y;
  }
};

// 4th-order Butterworth low- or high-pass at cutoff_hz (-3 dB there): two bilinear-transformed
// sections with the Butterworth pole quality factors 1/(2 cos(pi/8)) and 1/(2 cos(3 pi/8)).
struct Butterworth4 {
  Biquad sections[2];
  double step(double x) { return sections[1].step(sections[0].step(x)); }
};
Butterworth4 butterworth4_lowpass(double cutoff_hz, double sample_rate_hz);
Butterworth4 butterworth4_highpass(double cutoff_hz, double sample_rate_hz);

// Linear convolution of x with h, the first out_frames samples (zero-padded FFT, FFTW r2c/c2r).
std::vector<double> convolve_fft(const std::vector<double>& x, const std::vector<double>& h, std::size_t out_frames);

// Stationary Gaussian noise of the given RMS whose spectrum falls above corner_hz: white mixed with the
// same white through a one-pole low-pass (a microphone preamp and room hum are not white).
std::vector<double> tilted_noise(std::size_t frames, double rms, double corner_hz, double sample_rate_hz,
                                 std::mt19937_64& rng);

double rms_of(const std::vector<double>& x, std::size_t begin, std::size_t end);

}  // namespace ms::indep
