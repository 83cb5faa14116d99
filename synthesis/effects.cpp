#include "synthesis/effects.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <random>

#include "synthesis/fft.hpp"

namespace ms {

void apply_support_damping(ModalModel& model, const SupportDamping& support) {
  std::mt19937_64 rng(support.seed);
  std::exponential_distribution<double> excess(
      support.exponential_mean_per_s > 0 ? 1.0 / support.exponential_mean_per_s : 1.0);
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    double add = support.extra_decay_per_s;
    if (n < support.per_mode_decay_per_s.size()) add += support.per_mode_decay_per_s[n];
    if (support.exponential_mean_per_s > 0) add += excess(rng);
    model.modes[n].decay_per_s += add;
  }
}

namespace {

bool splits(const Doublets& doublets, const std::vector<int>& orders, std::size_t n) {
  return orders.empty() || (n < orders.size() && orders[n] >= doublets.min_order);
}

}  // namespace

double lowest_split_freq_hz(const ModalModel& model, const Doublets& doublets, const std::vector<int>& orders) {
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < model.modes.size(); ++n)
    if (splits(doublets, orders, n)) lowest = std::min(lowest, model.modes[n].freq_hz);
  return lowest;
}

void apply_doublets(ModalModel& model, const Doublets& doublets, const std::vector<int>& orders) {
  if (doublets.split_rel <= 0 && doublets.split_hz <= 0) return;
  if (doublets.split_hz > 0 ? doublets.split_hz >= 2.0 * lowest_split_freq_hz(model, doublets, orders)
                            : doublets.split_rel >= 2.0)
    throw std::invalid_argument("apply_doublets: the split would put a mode at or below 0 Hz");
  ModalModel out;
  out.hit_point_names = model.hit_point_names;
  out.hit_gains.resize(model.hit_gains.size());
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    const Mode& m = model.modes[n];
    const bool split = splits(doublets, orders, n);
    auto copy_gain = [&](std::size_t times) {
      for (std::size_t h = 0; h < model.hit_gains.size(); ++h)
        for (std::size_t k = 0; k < times; ++k)
          out.hit_gains[h].push_back(n < model.hit_gains[h].size() ? model.hit_gains[h][n] : 1.0);
    };
    if (!split) {
      out.modes.push_back(m);
      copy_gain(1);
      continue;
    }
    const double delta = doublets.split_hz > 0 ? doublets.split_hz : doublets.split_rel * m.freq_hz;
    Mode lower = m, upper = m;
    lower.freq_hz = m.freq_hz - 0.5 * delta;
    upper.freq_hz = m.freq_hz + 0.5 * delta;
    lower.amp = (1.0 - doublets.balance) * m.amp;
    upper.amp = doublets.balance * m.amp;
    out.modes.push_back(lower);
    out.modes.push_back(upper);
    copy_gain(2);
  }
  model = std::move(out);
}

void add_background_noise(std::vector<float>& samples, const BackgroundNoise& noise) {
  if (!noise.enabled || samples.empty()) return;
  double power = 0.0;
  for (float v : samples) power += double(v) * v;
  power /= double(samples.size());
  const double sigma = std::sqrt(power / std::pow(10.0, noise.snr_db / 10.0));
  std::mt19937_64 rng(noise.seed);
  std::normal_distribution<double> gauss(0.0, sigma);
  for (float& v : samples) v = float(v + gauss(rng));
}

std::size_t hold_samples(double hold_s, double sample_rate_hz) {
  return hold_s > 0.0 ? std::size_t(std::lround(hold_s * sample_rate_hz)) : 0;
}

double decaying_noise_variance(double direct_energy, double sample_rate_hz, std::size_t n, double t60_s,
                               double energy_db, double hold_s) {
  // The held samples, then sum_t exp(-2 k t) in closed form (geometric series), k = ln(1000) / t60 per sample.
  const std::size_t held = std::min(hold_samples(hold_s, sample_rate_hz), n);
  const double r = std::exp(-2.0 * std::log(1000.0) / (t60_s * sample_rate_hz));
  const double envelope_energy = double(held) + (1.0 - std::pow(r, double(n - held))) / (1.0 - r);
  return direct_energy * std::pow(10.0, energy_db / 10.0) / std::max(envelope_energy, 1e-300);
}

double noise_envelope(std::size_t i, std::size_t held, double decay_per_sample) {
  return i < held ? 1.0 : std::exp(-decay_per_sample * double(i - held));
}

void add_decaying_noise(std::vector<float>& samples, double sample_rate_hz, double t60_s, double energy_db,
                        std::uint64_t seed, double hold_s) {
  if (samples.empty() || t60_s <= 0) return;
  double energy = 0.0;
  for (float v : samples) energy += double(v) * v;
  const double sigma0 =
      std::sqrt(decaying_noise_variance(energy, sample_rate_hz, samples.size(), t60_s, energy_db, hold_s));
  const double k = std::log(1000.0) / (t60_s * sample_rate_hz);
  const std::size_t held = hold_samples(hold_s, sample_rate_hz);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double env = sigma0 * noise_envelope(i, held, k);
    if (env < 1e-12 * sigma0) break;  // 240 dB down: nothing left to add
    samples[i] = float(samples[i] + env * gauss(rng));
  }
}

double burst_band_gain2(double freq_hz, double low_hz, double high_hz) {
  if (high_hz <= 0.0) return 1.0;
  const double high = 1.0 / (1.0 + std::pow(freq_hz / high_hz, 8.0));
  return low_hz > 0.0 ? high / (1.0 + std::pow(low_hz / std::max(freq_hz, 1e-9 * low_hz), 8.0)) : high;
}

double band_power_share(double low_hz, double high_hz, double sample_rate_hz) {
  if (high_hz <= 0.0) return 1.0;
  // The mean of |H|^2 from 0 to Nyquist (midpoint rule on 8192 points: the edges span hundreds).
  constexpr int kPoints = 8192;
  const double nyquist = 0.5 * sample_rate_hz;
  double sum = 0.0;
  for (int i = 0; i < kPoints; ++i) sum += burst_band_gain2((i + 0.5) * nyquist / kPoints, low_hz, high_hz);
  return std::max(sum / kPoints, 1e-12);
}

namespace {

// The burst's noise band-limited: stationary white noise shaped by the band's |H| (circularly: it has
// no onset to ring before), scaled to unit variance, then given add_decaying_noise's envelope. Its power
// spectrum is |H|^2, blurred by the envelope's own width (1 / the decay time).
void add_band_limited_burst(std::vector<float>& samples, const std::vector<float>& direct, double sample_rate_hz,
                            const AttackTransient& t) {
  const double t60_s = 1e-3 * t.duration_ms, hold_s = 1e-3 * t.hold_ms;
  const std::size_t held = hold_samples(hold_s, sample_rate_hz);
  const std::size_t span = std::min(direct.size(), held + std::size_t(4.0 * t60_s * sample_rate_hz) + 1);  // 240 dB down
  double energy = 0.0;
  for (float v : direct) energy += double(v) * v;
  const double sigma0 =
      std::sqrt(decaying_noise_variance(energy, sample_rate_hz, direct.size(), t60_s, t.level_db, hold_s));
  const double k = std::log(1000.0) / (t60_s * sample_rate_hz);
  std::mt19937_64 rng(t.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  RealFft fft(nice_fft_size(span), RealFft::Directions::forward_and_backward);
  const std::size_t n = fft.size();
  for (std::size_t i = 0; i < n; ++i) fft.real()[i] = gauss(rng);
  fft.forward();
  const double bin_hz = sample_rate_hz / double(n);
  double kept = 0.0;  // the variance the shaping keeps, in bins
  for (std::size_t b = 0; b <= n / 2; ++b) {
    const double h2 = burst_band_gain2(double(b) * bin_hz, t.low_hz, t.high_hz);
    fft.spectrum()[b] *= std::sqrt(h2);
    kept += (b == 0 || 2 * b == n ? 1.0 : 2.0) * h2;
  }
  fft.backward();
  const double unit = 1.0 / (double(n) * std::sqrt(std::max(kept, 1e-12) / double(n)));
  for (std::size_t i = 0; i < samples.size() && i < span; ++i)
    samples[i] = float(samples[i] + sigma0 * noise_envelope(i, held, k) * fft.real()[i] * unit);
}

}  // namespace

void add_reverb_and_transient(std::vector<float>& samples, double sample_rate_hz, const Reverb& reverb,
                              const AttackTransient& transient) {
  const std::vector<float> direct = samples;
  if (reverb.enabled) {
    std::vector<float> tail(direct);
    add_decaying_noise(tail, sample_rate_hz, reverb.rt60_s, reverb.level_db, reverb.seed);
    for (std::size_t i = 0; i < samples.size(); ++i) samples[i] += tail[i] - direct[i];
  }
  if (transient.enabled && transient.band_limited()) {
    add_band_limited_burst(samples, direct, sample_rate_hz, transient);
  } else if (transient.enabled) {
    std::vector<float> burst(direct);
    add_decaying_noise(burst, sample_rate_hz, 1e-3 * transient.duration_ms, transient.level_db, transient.seed,
                       1e-3 * transient.hold_ms);
    for (std::size_t i = 0; i < samples.size(); ++i) samples[i] += burst[i] - direct[i];
  }
}

}  // namespace ms
