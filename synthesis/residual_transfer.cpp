// Feature-guided residual transfer (Algorithm 1); see residual_transfer.hpp.
#include "synthesis/residual_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace ms {

namespace {

// A rectangle of a spectrogram, frames [0, frames) x bins [bin0, bin0 + width), zero outside.
struct Patch {
  std::size_t frames = 0, bin0 = 0, width = 0;
  std::vector<double> values;

  double at(long long m, long long k) const {
    if (m < 0 || m >= (long long)frames || k < (long long)bin0 || k >= (long long)(bin0 + width)) return 0.0;
    return values[std::size_t(m) * width + std::size_t(k - (long long)bin0)];
  }
  // Bilinear in (frame, bin); an integer position returns its pixel exactly.
  double sample(double frame, double bin) const {
    const double m0 = std::floor(frame), k0 = std::floor(bin);
    const double wm = frame - m0, wk = bin - k0;
    const long long m = (long long)m0, k = (long long)k0;
    double v = (1.0 - wm) * (1.0 - wk) * at(m, k);
    if (wk > 0.0) v += (1.0 - wm) * wk * at(m, k + 1);
    if (wm > 0.0) {
      v += wm * (1.0 - wk) * at(m + 1, k);
      if (wk > 0.0) v += wm * wk * at(m + 1, k + 1);
    }
    return v;
  }
  void resize(std::size_t f, std::size_t b0, std::size_t w) {
    frames = f;
    bin0 = b0;
    width = w;
    values.resize(f * w);  // reused from pair to pair; grows only
  }
};

std::vector<Mode> by_frequency(std::vector<Mode> modes, double nyquist_hz) {
  std::erase_if(modes, [&](const Mode& m) { return !(m.freq_hz > 0.0 && m.freq_hz < nyquist_hz); });
  std::stable_sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) { return a.freq_hz < b.freq_hz; });
  return modes;
}

}  // namespace

std::vector<Mode> heard_modes(const std::vector<Mode>& modes, const Excitation& excitation) {
  const bool impulse = excitation.shape == PulseShape::impulse || excitation.contact_s <= 0.0;
  std::vector<Mode> heard = modes;
  for (Mode& m : heard) {
    std::complex<double> a = excitation.gain * std::polar(m.amp, m.phase_rad);
    if (!impulse) {
      // The free decay Im(a G e^{pt}) begins when the contact ends; its state then is the mode's start.
      const std::complex<double> p(-m.decay_per_s, 2.0 * std::numbers::pi * m.freq_hz);
      a *= contact_factor(excitation, m.decay_per_s, m.freq_hz) * std::exp(p * excitation.contact_s);
    }
    m.amp = std::abs(a);
    m.phase_rad = std::arg(a);
  }
  return heard;
}

std::vector<float> transfer_residual_power(const ResidualSpectrogram& source, const std::vector<Mode>& target,
                                           std::size_t target_frames) {
  const StftGrid& grid = source.grid;
  const std::size_t bins = grid.bins();
  const double fs = source.sample_rate_hz, bin_hz = fs / double(grid.fft_size);
  const std::vector<Mode> from = by_frequency(source.modes, 0.5 * fs), to = by_frequency(target, 0.5 * fs);
  const std::size_t pairs = std::min(from.size(), to.size());
  std::vector<float> out(target_frames * bins, 0.0f);
  if (target_frames == 0) return out;
  if (pairs == 0) {
    std::copy_n(source.power.begin(), std::min(source.frames, target_frames) * bins, out.begin());
    return out;
  }
  double loudest_source = 0.0;
  for (const Mode& m : from) loudest_source = std::max(loudest_source, m.amp);
  Patch residual, source_mode, target_mode;
  std::vector<double> moved_mode(bins);  // one frame of the moved source mode, reused
  for (std::size_t i = 0; i < pairs; ++i) {
    const Mode& s = from[i];
    const Mode& t = to[i];
    // The target neighbourhood: bins whose frequency lies between the midpoints to the paired neighbours.
    const double lo_hz = i == 0 ? -std::numeric_limits<double>::infinity() : 0.5 * (to[i - 1].freq_hz + t.freq_hz);
    const double hi_hz = i + 1 == pairs ? std::numeric_limits<double>::infinity() : 0.5 * (t.freq_hz + to[i + 1].freq_hz);
    std::size_t k_begin = 0, k_end = bins;
    while (k_begin < bins && double(k_begin) * bin_hz < lo_hz) ++k_begin;
    while (k_end > k_begin && double(k_end - 1) * bin_hz >= hi_hz) --k_end;
    if (k_begin == k_end) continue;
    const double shift_bins = (t.freq_hz - s.freq_hz) / bin_hz;
    const double time_ratio = s.decay_per_s > 0.0 && t.decay_per_s > 0.0 ? t.decay_per_s / s.decay_per_s : 1.0;

    // Source pixels the neighbourhood reads: frames up to (target_frames - 1) * ratio, bins shifted back.
    const std::size_t src_frames =
        std::size_t(std::min(double(source.frames), std::floor(double(target_frames - 1) * time_ratio) + 2.0));
    const double lowest = std::floor(double(k_begin) - shift_bins), highest = std::floor(double(k_end - 1) - shift_bins) + 2.0;
    const std::size_t src_k0 = std::size_t(std::clamp(lowest, 0.0, double(bins)));
    const std::size_t src_k1 = std::size_t(std::clamp(highest, 0.0, double(bins)));
    residual.resize(src_frames, src_k0, src_k1 - src_k0);
    for (std::size_t m = 0; m < src_frames; ++m)
      for (std::size_t k = src_k0; k < src_k1; ++k) residual.values[m * residual.width + (k - src_k0)] = source.at(m, k);
    // The source mode shifted is exactly the same sinusoid at the target frequency; it is stretched
    // like the residual, by interpolation between its frames.
    const Mode shifted{t.freq_hz, s.decay_per_s, s.amp, s.phase_rad};
    source_mode.resize(src_frames, k_begin, k_end - k_begin);
    damped_sine_power(shifted, fs, grid, 0, src_frames, k_begin, k_end, source_mode.values.data());
    target_mode.resize(target_frames, k_begin, k_end - k_begin);
    damped_sine_power(t, fs, grid, 0, target_frames, k_begin, k_end, target_mode.values.data());

    // Below this (-120 dB under the source sine's peak, a^2 N^2 / 16) the moved source mode is gone.
    const double present_s = 1e-12 * s.amp * s.amp * double(grid.fft_size) * double(grid.fft_size) / 16.0;
    // A source mode 120 dB under the loudest (struck at its node) guides nothing.
    const bool audible_source = s.amp > 1e-6 * loudest_source;
    for (std::size_t m = 0; m < target_frames; ++m) {
      const double frame = double(m) * time_ratio;
      // The source mode moved like the residual, and both modes' peaks in this frame (for the floor).
      double peak_s = 0.0, peak_t = 0.0;
      for (std::size_t k = k_begin; k < k_end; ++k) {
        moved_mode[k - k_begin] = source_mode.sample(frame, double(k));
        peak_s = std::max(peak_s, moved_mode[k - k_begin]);
        peak_t = std::max(peak_t, target_mode.at((long long)m, (long long)k));
      }
      for (std::size_t k = k_begin; k < k_end; ++k) {
        const double moved = residual.sample(frame, double(k) - shift_bins);
        if (moved == 0.0) continue;
        const double below = moved_mode[k - k_begin] + kPixelScaleFloor * peak_s;
        double scale = 1.0;  // a silent source mode says nothing about how its neighbourhood changes
        if (audible_source)
          scale = peak_s > present_s ? (target_mode.at((long long)m, (long long)k) + kPixelScaleFloor * peak_t) / below
                                     : (t.amp * t.amp) / (s.amp * s.amp);  // the source mode has died away here
        out[m * bins + k] = float(std::min(scale, kMaxPixelScale) * moved);
      }
    }
  }
  return out;
}

GriffinLimResult render_transferred_residual(const ResidualSpectrogram& source, const std::vector<Mode>& target,
                                             double sample_rate_hz, std::size_t samples,
                                             const GriffinLimOptions& options) {
  if (sample_rate_hz != source.sample_rate_hz)
    throw std::invalid_argument("residual made at " + std::to_string(source.sample_rate_hz) + " Hz used at " +
                                std::to_string(sample_rate_hz) + " Hz");
  const std::vector<float> power = transfer_residual_power(source, target, source.grid.frames_for(samples));
  return griffin_lim(power, source.grid, samples, options);
}

void add_transferred_residual(std::vector<float>& samples, const ResidualSpectrogram& source,
                              const std::vector<Mode>& target, double sample_rate_hz, double gain_db,
                              std::uint64_t seed) {
  GriffinLimOptions options;
  options.seed = seed;
  const GriffinLimResult residual = render_transferred_residual(source, target, sample_rate_hz, samples.size(), options);
  const double gain = std::pow(10.0, gain_db / 20.0);
  for (std::size_t i = 0; i < samples.size(); ++i) samples[i] += float(gain * residual.samples[i]);
}

}  // namespace ms
