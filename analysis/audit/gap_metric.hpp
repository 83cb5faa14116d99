// The audit's gap metric: Bark-band log spectrograms of a strike (measured or modelled) and the mean
// absolute difference between two of them in dB, with levels clamped to a floor below the strike's peak.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace ms::audit {

// Frame grid shared by every spectrogram of one audit: Hann window of ~23 ms (power of two), hop half
// a window, Zwicker-Terhardt Bark bands [z, z+1) from 0 Bark up to Nyquist.
struct SpectrogramGrid {
  double sample_rate_hz = 0.0;
  std::size_t window = 0;
  std::size_t hop = 0;
  std::size_t frames = 0;           // frames covering `samples` (each window fully inside)
  std::size_t bands = 0;
  std::vector<int> bin_band;        // per rfft bin: its Bark band, -1 for DC
  std::vector<std::size_t> band_bins;  // number of bins per band
  double window_energy = 0.0;       // sum w^2 (white noise of variance s^2 gives s^2 * this per bin)
  double frame_time_s(std::size_t frame) const;  // centre of a frame
  double band_centre_hz(std::size_t band) const;
};

SpectrogramGrid make_grid(double sample_rate_hz, std::size_t samples);

// Band powers (sum of |X_k|^2 over the band's bins), frames x bands, row-major.
struct BarkSpectrogram {
  std::size_t frames = 0, bands = 0;
  std::vector<double> power;
  double at(std::size_t frame, std::size_t band) const { return power[frame * bands + band]; }
  double& at(std::size_t frame, std::size_t band) { return power[frame * bands + band]; }
};

// x starts at the strike's onset; samples beyond grid.frames' reach are ignored, missing ones are 0.
BarkSpectrogram bark_spectrogram(const std::vector<float>& x, const SpectrogramGrid& grid);

constexpr double kGapFloorDb = 60.0;  // levels below (measured peak cell - 60 dB) are clamped to it
inline const char* kGapMetric =
    "mean |measured - model| Bark-band level (dB) over frames of ~23 ms, floor 60 dB below each "
    "strike's loudest cell, cells where both lie on the floor excluded, averaged over strikes";

// Per-cell signed difference model - measured in dB (NaN where both lie on the floor) and its mean
// absolute value: the gap of one strike.
struct GapMap {
  std::size_t frames = 0, bands = 0;
  std::vector<double> diff_db;
  double gap_db = 0.0;
};
GapMap gap_map(const BarkSpectrogram& measured, const BarkSpectrogram& model, double floor_db = kGapFloorDb);

double level_db(double power);  // 10 log10(power), -400 for 0

}  // namespace ms::audit
