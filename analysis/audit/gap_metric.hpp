// The audit's gap metric: Bark-band log spectrograms of a strike (measured or modelled) and the mean
// absolute difference between two of them in dB, with levels clamped to a floor below the strike's peak.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace ms::audit {

// Frame grid of one time resolution, shared by every spectrogram of one audit at that resolution: Hann
// window (power of two), hop half a window, Zwicker-Terhardt Bark bands [z, z+1) from 0 Bark up to
// Nyquist (at the attack's 2.9 ms a band narrower than a 345 Hz bin may hold none).
struct SpectrogramGrid {
  double sample_rate_hz = 0.0;
  std::size_t window = 0;
  std::size_t hop = 0;
  std::size_t samples = 0;          // length of the strike the grid belongs to
  std::size_t frames = 0;           // frames covering its first `span` samples (each window fully inside)
  std::size_t bands = 0;
  std::vector<int> bin_band;        // per rfft bin: its Bark band, -1 for DC
  std::vector<std::size_t> band_bins;  // number of bins per band
  double window_energy = 0.0;       // sum w^2 (white noise of variance s^2 gives s^2 * this per bin)
  std::vector<double> window_squared;  // w_i^2 of the Hann window, per sample (noise models weigh by it)
  double frame_time_s(std::size_t frame) const;  // centre of a frame
  double band_centre_hz(std::size_t band) const;
};

// Frames of window_s rounded up to a power of two (at least 64 samples), hop half a frame, covering
// the first `span` of a strike's `samples`.
SpectrogramGrid make_grid(double sample_rate_hz, std::size_t samples, double window_s = 0.023,
                          std::size_t span = std::size_t(-1));

// Band powers (sum of |X_k|^2 over the band's bins), frames x bands, row-major.
struct BarkSpectrogram {
  std::size_t frames = 0, bands = 0;
  std::vector<double> power;
  double at(std::size_t frame, std::size_t band) const { return power[frame * bands + band]; }
  double& at(std::size_t frame, std::size_t band) { return power[frame * bands + band]; }
};

// x starts at the strike's onset; samples beyond grid.frames' reach are ignored, missing ones are 0.
BarkSpectrogram bark_spectrogram(const std::vector<float>& x, const SpectrogramGrid& grid);

// The gap looks at a strike at two time resolutions: frames of ~23 ms over the whole strike (decays,
// floors, tails; 43 Hz bins resolve the first Bark band) and frames of ~2.9 ms over its first ~46 ms
// (the attack: a burst of a few ms fills a tenth of one long frame and barely moves it).
constexpr std::size_t kDecay = 0, kAttack = 1, kResolutions = 2;
constexpr double kAttackWindowS = 0.0029, kAttackSpanS = 0.046;
using Grids = std::array<SpectrogramGrid, kResolutions>;
using Spectra = std::array<BarkSpectrogram, kResolutions>;

Grids make_grids(double sample_rate_hz, std::size_t samples);
Spectra bark_spectra(const std::vector<float>& x, const Grids& grids);

constexpr double kGapFloorDb = 60.0;  // levels below (measured peak cell - 60 dB) are clamped to it
inline const char* kGapMetric =
    "mean |measured - model| Bark-band level (dB) over the cells of two spectrograms, frames of ~23 ms "
    "over the whole strike and of ~2.9 ms over its first ~46 ms (the attack), floor 60 dB below each "
    "spectrogram's loudest cell, cells where both lie on the floor excluded, averaged over strikes";

// Per-cell signed difference model - measured in dB (NaN where both lie on the floor) at the decay
// resolution (for pictures and locating), and the mean absolute value over the cells of both
// resolutions: the gap of one strike.
struct GapMap {
  std::size_t frames = 0, bands = 0;
  std::vector<double> diff_db;
  double gap_db = 0.0;
};
GapMap gap_map(const Spectra& measured, const Spectra& model, double floor_db = kGapFloorDb);

// One resolution's share of a gap: the sum of |model - measured| dB over its cells and their count
// (diff_db, if given, receives the signed per-cell differences, NaN where both lie on the floor).
struct GapSum {
  double sum_db = 0.0;
  std::size_t cells = 0;
};
GapSum gap_sum(const BarkSpectrogram& measured, const BarkSpectrogram& model, double floor_db = kGapFloorDb,
               std::vector<double>* diff_db = nullptr);

double level_db(double power);  // 10 log10(power), -400 for 0

}  // namespace ms::audit
