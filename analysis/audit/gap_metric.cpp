#include "analysis/audit/gap_metric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "synthesis/bark.hpp"
#include "synthesis/fft.hpp"

namespace ms::audit {

double level_db(double power) { return power > 0.0 ? 10.0 * std::log10(power) : -400.0; }

double SpectrogramGrid::frame_time_s(std::size_t frame) const {
  return (double(frame * hop) + 0.5 * double(window)) / sample_rate_hz;
}

double SpectrogramGrid::band_centre_hz(std::size_t band) const {
  // invert Zwicker-Terhardt by bisection (monotone)
  const double z = double(band) + 0.5;
  double lo = 0.0, hi = 0.5 * sample_rate_hz;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (bark_zwicker_terhardt(mid) < z ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

SpectrogramGrid make_grid(double fs, std::size_t samples, double window_s, std::size_t span) {
  SpectrogramGrid g;
  g.sample_rate_hz = fs;
  g.samples = samples;
  span = std::min(span, samples);
  g.window = 64;
  while (double(g.window) < window_s * fs) g.window *= 2;
  g.hop = g.window / 2;
  g.frames = span >= g.window ? 1 + (span - g.window) / g.hop : 0;
  const std::size_t bins = g.window / 2 + 1;
  g.bin_band.assign(bins, -1);
  int max_band = 0;
  for (std::size_t k = 1; k < bins; ++k) {
    const int b = int(std::floor(bark_zwicker_terhardt(double(k) * fs / double(g.window))));
    g.bin_band[k] = b;
    max_band = std::max(max_band, b);
  }
  g.bands = std::size_t(max_band) + 1;
  g.band_bins.assign(g.bands, 0);
  for (std::size_t k = 1; k < bins; ++k) ++g.band_bins[std::size_t(g.bin_band[k])];
  g.window_energy = 0.0;
  g.window_squared.resize(g.window);
  for (std::size_t i = 0; i < g.window; ++i) {
    const double w = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(i) / double(g.window));
    g.window_squared[i] = w * w;
    g.window_energy += w * w;
  }
  return g;
}

BarkSpectrogram bark_spectrogram(const std::vector<float>& x, const SpectrogramGrid& g) {
  BarkSpectrogram s;
  s.frames = g.frames;
  s.bands = g.bands;
  s.power.assign(g.frames * g.bands, 0.0);
  if (g.frames == 0) return s;
  const std::size_t bins = g.window / 2 + 1;
  RealFft fft(g.window);
  double* in = fft.real();
  const std::complex<double>* out = fft.spectrum();
  std::vector<double> w(g.window);
  for (std::size_t i = 0; i < g.window; ++i) w[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(i) / double(g.window));
  for (std::size_t f = 0; f < g.frames; ++f) {
    const std::size_t start = f * g.hop;
    for (std::size_t i = 0; i < g.window; ++i)
      in[i] = start + i < x.size() ? w[i] * double(x[start + i]) : 0.0;
    fft.forward();
    double* row = &s.power[f * g.bands];
    for (std::size_t k = 1; k < bins; ++k)
      row[std::size_t(g.bin_band[k])] += out[k].real() * out[k].real() + out[k].imag() * out[k].imag();
  }
  return s;
}

Grids make_grids(double fs, std::size_t samples) {
  return {make_grid(fs, samples), make_grid(fs, samples, kAttackWindowS, std::size_t(kAttackSpanS * fs))};
}

Spectra bark_spectra(const std::vector<float>& x, const Grids& grids) {
  Spectra s;
  for (std::size_t r = 0; r < kResolutions; ++r) s[r] = bark_spectrogram(x, grids[r]);
  return s;
}

GapSum gap_sum(const BarkSpectrogram& measured, const BarkSpectrogram& model, double floor_db,
               std::vector<double>* diff_db) {
  GapSum g;
  if (diff_db) diff_db->assign(measured.power.size(), std::numeric_limits<double>::quiet_NaN());
  double peak = -400.0;
  for (double p : measured.power) peak = std::max(peak, level_db(p));
  const double floor = peak - floor_db;
  for (std::size_t i = 0; i < measured.power.size() && i < model.power.size(); ++i) {
    const double a = std::max(level_db(measured.power[i]), floor), b = std::max(level_db(model.power[i]), floor);
    if (a <= floor && b <= floor) continue;
    if (diff_db) (*diff_db)[i] = b - a;
    g.sum_db += std::abs(b - a);
    ++g.cells;
  }
  return g;
}

GapMap gap_map(const Spectra& measured, const Spectra& model, double floor_db) {
  GapMap m;
  m.frames = measured[kDecay].frames;
  m.bands = measured[kDecay].bands;
  double sum = 0.0;
  std::size_t cells = 0;
  for (std::size_t r = 0; r < kResolutions; ++r) {
    const GapSum g = gap_sum(measured[r], model[r], floor_db, r == kDecay ? &m.diff_db : nullptr);
    sum += g.sum_db;
    cells += g.cells;
  }
  m.gap_db = cells > 0 ? sum / double(cells) : 0.0;
  return m;
}

}  // namespace ms::audit
