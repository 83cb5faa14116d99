// perceptual_profile / perceptual_distance_db: 20 ms Hann frames (FFTW), power summed per Bark band.
#include "studyapp/core/perceptual_distance.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "synthesis/bark.hpp"
#include "synthesis/fft.hpp"

namespace ms {

namespace {
constexpr std::size_t kBands = 25;      // Bark 0..24
constexpr std::size_t kEarlyFrames = 10;  // 10 x 20 ms: the attack and early decay
constexpr double kFloorDb = -140.0;
}  // namespace

PerceptualProfile perceptual_profile(const std::vector<float>& x, double fs) {
  const auto frame = std::max<std::size_t>(16, std::size_t(0.020 * fs));
  std::size_t n = 1;
  while (n < frame) n *= 2;
  RealFft fft(n);
  double* in = fft.real();
  const std::complex<double>* out = fft.spectrum();
  std::vector<std::size_t> band_of(n / 2 + 1);
  for (std::size_t k = 0; k < band_of.size(); ++k)
    band_of[k] = std::min<std::size_t>(kBands - 1, std::size_t(bark_zwicker_terhardt(double(k) * fs / double(n))));
  std::vector<double> window(frame);
  for (std::size_t i = 0; i < frame; ++i) window[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(i) / double(frame));

  const std::size_t frames_total = x.size() / frame;
  std::vector<double> whole(kBands, 0.0), broadband(frames_total, 0.0);
  PerceptualProfile p;
  p.level_db.assign((kEarlyFrames + 1) * kBands, kFloorDb);
  for (std::size_t f = 0; f < frames_total; ++f) {
    std::fill(in, in + n, 0.0);
    for (std::size_t i = 0; i < frame; ++i) in[i] = double(x[f * frame + i]) * window[i];
    fft.forward();
    std::vector<double> band(kBands, 0.0);
    for (std::size_t k = 1; k < band_of.size(); ++k)
      band[band_of[k]] += out[k].real() * out[k].real() + out[k].imag() * out[k].imag();
    for (std::size_t b = 0; b < kBands; ++b) {
      whole[b] += band[b];
      broadband[f] += band[b];
      if (f < kEarlyFrames) p.level_db[f * kBands + b] = std::max(kFloorDb, 10.0 * std::log10(band[b] + 1e-300));
    }
  }

  double total = 0.0, weighted = 0.0;
  for (std::size_t b = 0; b < kBands; ++b) {
    p.level_db[kEarlyFrames * kBands + b] = std::max(kFloorDb, 10.0 * std::log10(whole[b] + 1e-300));
    total += whole[b];
    weighted += whole[b] * (double(b) + 0.5);
  }
  p.centroid_bark = total > 0.0 ? weighted / total : 0.0;
  if (!broadband.empty()) {
    const auto peak = std::max_element(broadband.begin(), broadband.end());
    std::size_t end = std::size_t(peak - broadband.begin());
    while (end < broadband.size() && broadband[end] > *peak * 1e-3) ++end;  // -30 dB
    p.decay_s = double(end) * double(frame) / fs;
  }
  return p;
}

double perceptual_distance_db(const PerceptualProfile& a, const PerceptualProfile& b) {
  if (a.level_db.size() != b.level_db.size() || a.level_db.empty()) return 0.0;
  const double peak = std::max(*std::max_element(a.level_db.begin(), a.level_db.end()),
                               *std::max_element(b.level_db.begin(), b.level_db.end()));
  const double floor_db = peak - 60.0;  // differences below this are inaudible next to the peak
  double sum = 0.0;
  for (std::size_t i = 0; i < a.level_db.size(); ++i) {
    const double d = std::max(a.level_db[i], floor_db) - std::max(b.level_db[i], floor_db);
    sum += d * d;
  }
  return std::sqrt(sum / double(a.level_db.size()));
}

}  // namespace ms
