// Sub-band split of one real signal through its FFT: a band's bins, times a flat-top mask with
// raised-cosine skirts, are heterodyned to 0 Hz and inverse-transformed on a short grid, which gives
// the analytic band signal decimated to just above the mask's width. A mode inside the band stays an
// exact damped exponential once the (short, zero-phase) mask kernel has passed the onset.
#pragma once
#include <algorithm>
#include <complex>
#include <cstddef>
#include <map>
#include <memory>
#include <vector>

#include "analysis/extraction/noise_floor.hpp"
#include "synthesis/fft.hpp"

namespace ms {

struct BandSignal {
  std::vector<std::complex<double>> samples;  // analytic, heterodyned by center_hz
  double center_hz = 0.0;
  double rate_hz = 0.0;          // complex sample rate after decimation
  double noise_power = 0.0;      // E|noise|^2 per sample at the mask's flat top (white input)
  double noise_variance = 0.0;   // E|noise|^2 per sample through the whole mask
  std::size_t settle = 0;        // samples at the start (and end) disturbed by the mask kernel
};

class SubbandSplitter {
 public:
  // x: the real signal (its first sample is the time origin), sigma: white-noise std of x.
  // noise: coloured-noise profile (optional, must outlive the splitter); sigma is used where absent.
  SubbandSplitter(const std::vector<double>& x, double sample_rate_hz, double noise_sigma,
                  const NoiseProfile* noise = nullptr);
  ~SubbandSplitter();
  SubbandSplitter(const SubbandSplitter&) = delete;
  SubbandSplitter& operator=(const SubbandSplitter&) = delete;

  // Flat between center +- core_hz/2, raised-cosine skirts of skirt_hz each side.
  BandSignal band(double center_hz, double core_hz, double skirt_hz);

  // Largest |X(f)|^2 over [lo_hz, hi_hz] relative to the white-noise expectation of one bin.
  double peak_to_noise(double lo_hz, double hi_hz) const;

  double bin_hz() const { return bin_hz_; }
  std::size_t data_frames() const { return frames_; }

 private:
  ComplexInverseFft& plan_for(std::size_t size);  // one per decimated size, kept for the next band
  std::size_t frames_ = 0, fft_size_ = 0;
  double fs_ = 0.0, bin_hz_ = 0.0, sigma_ = 0.0;
  std::vector<std::complex<double>> spectrum_;  // bins 0..fft_size/2
  std::map<std::size_t, std::unique_ptr<ComplexInverseFft>> plans_;
  const NoiseProfile* noise_ = nullptr;
  double variance(double lo_hz, double hi_hz) const {
    return noise_ ? std::max(sigma_ * sigma_, noise_->max_variance(lo_hz, hi_hz)) : sigma_ * sigma_;
  }
};

}  // namespace ms
