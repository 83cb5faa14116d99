// Bark power and loudness images; see loudness_image.hpp.
#include "analysis/estimation/loudness_image.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include "analysis/estimation/iso226_loudness.hpp"
#include "synthesis/bark.hpp"
#include "synthesis/fft.hpp"

namespace ms {

namespace {

struct FftwBuffers {
  double* in;
  fftw_complex* out;
  explicit FftwBuffers(std::size_t n) : in(fftw_alloc_real(n)), out(fftw_alloc_complex(n / 2 + 1)) {}
  ~FftwBuffers() {
    fftw_free(out);
    fftw_free(in);
  }
  FftwBuffers(const FftwBuffers&) = delete;
  FftwBuffers& operator=(const FftwBuffers&) = delete;
};

}  // namespace

struct LoudnessImager::Plan {
  fftw_plan plan = nullptr;
};

double db_spl_at_unit_power_for_peak(const BarkImage& power, double peak_db_spl) {
  double peak = 0.0;
  for (double v : power.cells) peak = std::max(peak, v);
  return peak > 0.0 ? peak_db_spl - 10.0 * std::log10(peak) : 0.0;
}

double db_spl_at_unit_power_for_full_scale(double full_scale_db_spl) {
  return full_scale_db_spl - 10.0 * std::log10(0.5);
}

LoudnessImager::LoudnessImager(double fs, const LoudnessImageOptions& o)
    : sample_rate_hz_(fs), band_bark_(o.band_bark), plan_(std::make_unique<Plan>()) {
  if (!(fs > 0.0) || !(o.window_s > 0.0) || !(o.band_bark > 0.0))
    throw std::invalid_argument("LoudnessImager: sample rate, window and band width must be positive");
  window_ = 16;
  while (double(window_) < o.window_s * fs) window_ *= 2;
  hop_ = window_ / 2;
  hann_.resize(window_);
  double energy = 0.0;
  for (std::size_t n = 0; n < window_; ++n) {
    hann_[n] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(n) / double(window_));
    energy += hann_[n] * hann_[n];
  }
  power_scale_ = 2.0 / (double(window_) * energy);
  const std::size_t bands = std::size_t(bark_wang_sekey_gersho(fs / 2.0) / band_bark_) + 1;
  bin_band_.assign(window_ / 2 + 1, 0);
  for (std::size_t k = 1; k <= window_ / 2; ++k)
    bin_band_[k] = std::min(bands - 1, std::size_t(bark_wang_sekey_gersho(double(k) * fs / double(window_)) / band_bark_));
  band_centre_hz_.resize(bands);
  for (std::size_t b = 0; b < bands; ++b)
    band_centre_hz_[b] = 600.0 * std::sinh((double(b) + 0.5) * band_bark_ / 6.0);
  FftwBuffers buf(window_);
  // FFTW's planner is not thread-safe: every plan in the process is made under synthesis/fft's lock
  // (images are made on worker threads while stimuli are rendered on others).
  const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  plan_->plan = fftw_plan_dft_r2c_1d(int(window_), buf.in, buf.out, FFTW_ESTIMATE);
}

LoudnessImager::~LoudnessImager() {
  if (plan_ && plan_->plan) {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(plan_->plan);
  }
}

std::size_t LoudnessImager::band_of_hz(double freq_hz) const {
  const double b = std::floor(bark_wang_sekey_gersho(std::max(0.0, freq_hz)) / band_bark_);
  return b >= double(bands()) ? bands() : std::size_t(b);
}

BarkImage LoudnessImager::power(const std::vector<float>& x) const {
  BarkImage img;
  img.bands = bands();
  img.hop_s = double(hop_) / sample_rate_hz_;
  img.band_bark = band_bark_;
  img.frames = x.empty() ? 0 : x.size() < window_ ? 1 : (x.size() - window_) / hop_ + 1;
  img.cells.assign(img.frames * img.bands, 0.0);
  FftwBuffers buf(window_);  // fftw_alloc: the plan's alignment, as new-array execution requires
  for (std::size_t m = 0; m < img.frames; ++m) {
    const std::size_t start = m * hop_;
    for (std::size_t n = 0; n < window_; ++n)
      buf.in[n] = start + n < x.size() ? hann_[n] * double(x[start + n]) : 0.0;
    fftw_execute_dft_r2c(plan_->plan, buf.in, buf.out);
    double* row = &img.cells[m * img.bands];
    for (std::size_t k = 1; k <= window_ / 2; ++k) {
      const double p = buf.out[k][0] * buf.out[k][0] + buf.out[k][1] * buf.out[k][1];
      row[bin_band_[k]] += (k == window_ / 2 ? 0.5 : 1.0) * power_scale_ * p;
    }
  }
  return img;
}

BarkImage LoudnessImager::loudness(const BarkImage& power, double db_spl_at_unit_power) const {
  if (power.bands != bands()) throw std::invalid_argument("LoudnessImager::loudness: image from another grid");
  std::vector<ToneLoudness> tone;
  tone.reserve(bands());
  for (double f : band_centre_hz_) tone.emplace_back(iso226_parameters(f), db_spl_at_unit_power);
  BarkImage img = power;
  for (std::size_t m = 0; m < img.frames; ++m)
    for (std::size_t b = 0; b < img.bands; ++b) img.at(m, b) = tone[b].sone(power.at(m, b));
  return img;
}

}  // namespace ms
