// The loudness image of a sound (Ren et al., patent US 9,401,684 Sec. 5.2.1): its power spectrogram
// (Hann frames, FFTW) with the frequency axis mapped to critical-band rate (Wang-Sekey-Gersho
// z = 6 asinh(f/600), synthesis/bark.hpp) by summing bins into bands of band_bark, each cell's mean
// square turned into dB SPL by a calibration, then into phon through the ISO 226:2003 contour at the
// band's centre frequency and into sone (iso226_loudness.hpp). Masking is ignored, as in the patent.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

namespace ms {

struct LoudnessImageOptions {
  double window_s = 0.023;  // frame length, rounded up to a power of two (1024 samples at 44.1 kHz)
  double band_bark = 1.0;   // width of the Bark bands; 1 Bark is one critical band (powers in it add)
};

// A frames x bands image, row-major: a band mean square (digital units squared, so a sine of
// amplitude A in one band gives A^2/2 there) or a loudness (sone).
struct BarkImage {
  std::size_t frames = 0, bands = 0;
  double hop_s = 0.0;      // frame m covers [m hop, m hop + window) of the input
  double band_bark = 1.0;  // band b is [b, b + 1) * band_bark Bark
  std::vector<double> cells;
  double at(std::size_t frame, std::size_t band) const { return cells[frame * bands + band]; }
  double& at(std::size_t frame, std::size_t band) { return cells[frame * bands + band]; }
};

// Calibrations: the SPL [dB] a mean square of 1 (full-scale units squared) is played at.
// The loudest cell of `power` at peak_db_spl (a recording of unknown gain: the reference fixes it and
// the other sound is played with the same gain), 0 dB SPL when the image is silent.
double db_spl_at_unit_power_for_peak(const BarkImage& power, double peak_db_spl);
// A full-scale sine (mean square 1/2) at full_scale_db_spl.
double db_spl_at_unit_power_for_full_scale(double full_scale_db_spl);

// The frame grid, band map and FFTW plan of one sample rate, made once and reused for every image
// (the estimation makes thousands). power() and loudness() are const and may run on several threads;
// the constructor plans under a lock private to this file.
class LoudnessImager {
 public:
  explicit LoudnessImager(double sample_rate_hz, const LoudnessImageOptions& options = {});
  ~LoudnessImager();
  LoudnessImager(const LoudnessImager&) = delete;
  LoudnessImager& operator=(const LoudnessImager&) = delete;

  // Band mean squares of x from its first sample: frames wholly inside x (one zero-padded frame when
  // x is shorter than a window, none when it is empty), hop half a window, periodic Hann window.
  // Power per bin is 2|X_k|^2 / (N sum w^2) (once for the Nyquist bin), so the bins of a band sum to
  // the mean square of what lies in it; the 0 Hz bin is left out.
  BarkImage power(const std::vector<float>& x) const;

  // The image in sone: every cell through ToneLoudness at its band's centre frequency.
  BarkImage loudness(const BarkImage& power, double db_spl_at_unit_power) const;

  double sample_rate_hz() const { return sample_rate_hz_; }
  std::size_t window() const { return window_; }
  std::size_t hop() const { return hop_; }
  std::size_t bands() const { return band_centre_hz_.size(); }
  double band_bark() const { return band_bark_; }
  double band_centre_hz(std::size_t band) const { return band_centre_hz_[band]; }
  // The band a frequency falls in (bands() when at or above the last band).
  std::size_t band_of_hz(double freq_hz) const;
  const std::vector<double>& window_samples() const { return hann_; }

 private:
  struct Plan;
  double sample_rate_hz_;
  double band_bark_;
  std::size_t window_, hop_;
  std::vector<double> hann_;
  double power_scale_;                 // 2 / (N sum w^2)
  std::vector<std::size_t> bin_band_;  // per rfft bin 1..N/2 (index k)
  std::vector<double> band_centre_hz_;
  std::unique_ptr<Plan> plan_;
};

}  // namespace ms
