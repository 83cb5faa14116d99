#include "analysis/audit/room_power.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace ms::audit {

namespace {

// sum_{i >= 1} e^{-2 k i}: the reverberant energy per unit of white-equivalent variance.
double tail_sum(double k_per_sample) { return 1.0 / std::expm1(2.0 * k_per_sample); }

// The part of the spectrum [0, fs/2] an octave band covers (the response's noise is white before it
// is split).
double band_share(std::size_t b, double fs) {
  const double hi = std::min(room_octave_upper_edge_hz(b), 0.5 * fs), lo = std::min(room_octave_lower_edge_hz(b), hi);
  return (hi - lo) / (0.5 * fs);
}

}  // namespace

double hann2_decay_sum(double r, std::size_t n) {
  // w^2 = 3/8 - 1/2 cos(theta j) + 1/8 cos(2 theta j), theta = 2 pi / n: three geometric sums.
  const double theta = 2.0 * std::numbers::pi / double(n);
  const auto geometric = [&](double harmonic) {
    const std::complex<double> z = std::exp(std::complex<double>(-2.0 * r, harmonic * theta));
    if (std::abs(1.0 - z) < 1e-12) return double(n);
    return ((1.0 - std::exp(double(n) * std::complex<double>(-2.0 * r, harmonic * theta))) / (1.0 - z)).real();
  };
  return 0.375 * geometric(0.0) - 0.5 * geometric(1.0) + 0.125 * geometric(2.0);
}

double room_sigma2(const std::array<double, kRoomBands>& k, double drr_db, double fs) {
  double per_variance = 0.0;  // expected reverberant energy for sigma^2 = 1
  for (std::size_t b = 0; b < kRoomBands; ++b) per_variance += band_share(b, fs) * tail_sum(k[b]);
  return std::pow(10.0, -drr_db / 10.0) / per_variance;
}

RoomRates room_rates(const Room& room, double fs) {
  RoomRates r;
  for (std::size_t b = 0; b < kRoomBands; ++b) r.k_per_sample[b] = std::log(1000.0) / (room.band_rt60_s(b) * fs);
  r.sigma2 = room_sigma2(r.k_per_sample, room.drr_db, fs);
  return r;
}

double room_drr_db(const RoomRates& rates, double fs) {
  double energy = 0.0;
  for (std::size_t b = 0; b < kRoomBands; ++b) energy += band_share(b, fs) * rates.sigma2 * tail_sum(rates.k_per_sample[b]);
  return -10.0 * std::log10(energy);
}

double band_reverb_ratio(const RoomRates& rates, std::size_t band) {
  return rates.sigma2 * tail_sum(rates.k_per_sample[band]);
}

double dry_power_scale(const RoomRates& rates, std::size_t band, double delta) {
  const double k = rates.k_per_sample[band];
  // Slow modes: the extraction measures the amplitude they settle at, (1 + sigma^2 sum e^{-2 (k - d) i})
  // times the dry one in expectation. Towards the room's rate that part and the room's tail merge;
  // fast modes are measured by their direct sound (a gain falling as (k / 2d)^2 from d = k / 2 on).
  const double gain = delta <= 0.5 * k ? rates.sigma2 * tail_sum(k - delta)
                                       : rates.sigma2 * tail_sum(0.5 * k) * std::pow(0.5 * k / delta, 2);
  return 1.0 / (1.0 + gain);
}

void make_dry(ModalModel& modes, const RoomRates& rates, double fs) {
  for (Mode& m : modes.modes) m.amp *= std::sqrt(dry_power_scale(rates, room_octave_band(m.freq_hz), m.decay_per_s / fs));
}

RoomGrid room_grid(const SpectrogramGrid& g) {
  RoomGrid t;
  const double bin_hz = g.sample_rate_hz / double(g.window);
  t.band_lo_hz.assign(g.bands, 0.0);
  t.band_hi_hz.assign(g.bands, 0.0);
  std::vector<bool> seen(g.bands, false);
  for (std::size_t k = 1; k < g.bin_band.size(); ++k) {
    const std::size_t b = std::size_t(g.bin_band[k]);
    if (!seen[b]) t.band_lo_hz[b] = (double(k) - 0.5) * bin_hz;
    seen[b] = true;
    t.band_hi_hz[b] = (double(k) + 0.5) * bin_hz;
  }
  for (std::size_t b = 0; b < g.bands; ++b)
    t.band_octave.push_back(room_octave_band(0.5 * (t.band_lo_hz[b] + t.band_hi_hz[b])));
  return t;
}

std::vector<std::pair<std::size_t, double>> window_leakage(const SpectrogramGrid& g, double freq_hz) {
  // Shares under -60 dB of the tone lie under the gap's floor (60 dB below the strike's loudest cell).
  constexpr double kLeakageFloor = 1e-6;
  // |Hann kernel|^2 at x bins from the tone: (sin(pi x) / (pi x (1 - x^2)))^2 (large windows).
  const double centre = freq_hz * double(g.window) / g.sample_rate_hz;
  std::vector<double> band(g.bands, 0.0);
  double total = 0.0;
  for (std::size_t k = 1; k < g.bin_band.size(); ++k) {
    const double x = double(k) - centre;
    double p = 1.0;
    if (std::abs(std::abs(x) - 1.0) < 1e-9) p = 0.25;
    else if (std::abs(x) >= 1e-9) p = std::pow(std::sin(std::numbers::pi * x) / (std::numbers::pi * x * (1.0 - x * x)), 2);
    band[std::size_t(g.bin_band[k])] += p;
    total += p;
  }
  std::vector<std::pair<std::size_t, double>> out;
  for (std::size_t b = 0; b < g.bands; ++b)
    if (total > 0.0 && band[b] > kLeakageFloor * total) out.emplace_back(b, band[b] / total);
  return out;
}

RoomFootprint room_footprint(const SpectrogramGrid& g, const RoomGrid& rg, const ModalModel& rendered,
                             const RoomRates* as_rendered) {
  RoomFootprint fp;
  fp.onset_scale.fill(1.0);
  if (as_rendered)
    for (std::size_t o = 0; o < kRoomBands; ++o) fp.onset_scale[o] = dry_power_scale(*as_rendered, o, 0.0);
  const double fs = g.sample_rate_hz;
  std::vector<int> own_band;
  std::vector<std::complex<double>> gains, poles;  // y = Im(g e^{p t}), p in 1/s
  for (std::size_t index = 0; index < rendered.modes.size(); ++index) {
    const Mode& m = rendered.modes[index];
    if (m.freq_hz <= 0.0 || m.freq_hz >= 0.5 * fs || m.amp == 0.0) continue;
    RoomFootprint::ModeTerms t;
    t.owner = index;
    t.octave = room_octave_band(m.freq_hz);
    t.delta = m.decay_per_s / fs;
    t.a2 = m.amp * m.amp;
    if (as_rendered) t.rendered_scale = dry_power_scale(*as_rendered, t.octave, t.delta);
    t.window_sum = hann2_decay_sum(t.delta, g.window);
    t.per_hop = std::exp(-2.0 * t.delta * double(g.hop));
    // sum_j w_j^2 j e^{-2 delta j} = -d/d(2 delta) of window_sum (central difference of the closed form).
    const double h = 1e-4 * t.delta + 1e-9;
    t.ramp_sum = (hann2_decay_sum(t.delta - h, g.window) - hann2_decay_sum(t.delta + h, g.window)) / (4.0 * h);
    t.leakage = window_leakage(g, m.freq_hz);
    const std::size_t bin = std::clamp<std::size_t>(std::size_t(std::lround(m.freq_hz * double(g.window) / fs)), 1,
                                                    g.bin_band.size() - 1);
    own_band.push_back(g.bin_band[bin]);
    // The share of the mode's spectrum f_n^2 / ((f_n^2 - f^2)^2 + (f d / pi)^2) outside its own band
    // (whose total, the Lorentzian near f_n, is pi^2 / d) is onset transient, not narrowband.
    const auto spectrum = [&](double f) {
      const double u = m.freq_hz * m.freq_hz - f * f, v = f * m.decay_per_s / std::numbers::pi;
      return m.freq_hz * m.freq_hz / (u * u + v * v);
    };
    const double area = std::numbers::pi * std::numbers::pi / std::max(m.decay_per_s, 1e-9);
    for (std::size_t b = 0; b < g.bands; ++b) {
      if (int(b) == own_band.back() || g.band_bins[b] == 0) continue;
      constexpr int kPoints = 16;  // Simpson's rule: smooth away from the mode's own band
      const double lo = rg.band_lo_hz[b], step = (rg.band_hi_hz[b] - lo) / kPoints;
      double sum = spectrum(lo) + spectrum(lo + kPoints * step);
      for (int i = 1; i < kPoints; ++i) sum += (i % 2 ? 4.0 : 2.0) * spectrum(lo + i * step);
      t.own_share -= sum * step / 3.0 / area;
    }
    t.own_share = std::max(t.own_share, 0.0);
    fp.modes.push_back(std::move(t));
    gains.push_back(std::polar(m.amp, m.phase_rad));
    poles.emplace_back(-m.decay_per_s, 2.0 * std::numbers::pi * m.freq_hz);
  }
  // Onset energy per band from the modes outside it, summed coherently (Parseval: the energy of the
  // band's part of x is 2 int_band |X(f)|^2 df), by octave band of the modes.
  fp.onset_gram.assign(g.bands, {});
  for (std::size_t b = 0; b < g.bands; ++b) {
    if (g.band_bins[b] == 0) continue;
    constexpr int kPoints = 16;
    const double lo = rg.band_lo_hz[b], step = (rg.band_hi_hz[b] - lo) / kPoints;
    auto& gram = fp.onset_gram[b];
    for (int i = 0; i <= kPoints; ++i) {
      const double weight = (i == 0 || i == kPoints ? 1.0 : (i % 2 ? 4.0 : 2.0)) * step / 3.0;
      const std::complex<double> s(0.0, 2.0 * std::numbers::pi * (lo + i * step));
      std::array<std::complex<double>, kRoomBands> x{};
      for (std::size_t n = 0; n < fp.modes.size(); ++n) {
        if (own_band[n] == int(b)) continue;
        // Fourier transform of Im(g e^{p t}) for t >= 0: (g / (s - p) - conj(g) / (s - conj p)) / 2i
        // (divisions written out: std::complex's guards against infinities cost more than the rest).
        const auto over = [](std::complex<double> num, std::complex<double> den) { return num * std::conj(den) / std::norm(den); };
        x[fp.modes[n].octave] += (over(gains[n], s - poles[n]) - over(std::conj(gains[n]), s - std::conj(poles[n]))) *
                                 std::complex<double>(0.0, -0.5);
      }
      for (std::size_t o = 0; o < kRoomBands; ++o)
        for (std::size_t p = 0; p < kRoomBands; ++p)
          gram[o * kRoomBands + p] += weight * 2.0 * (x[o] * std::conj(x[p])).real() * fs;
    }
  }
  return fp;
}

RoomFrameSums room_frame_sums(const SpectrogramGrid& g, const RoomRates& rates) {
  RoomFrameSums sums;
  for (std::size_t b = 0; b < kRoomBands; ++b) {
    sums.frame_sum[b] = hann2_decay_sum(rates.k_per_sample[b], g.window);
    sums.per_hop[b] = std::exp(-2.0 * rates.k_per_sample[b] * double(g.hop));
  }
  return sums;
}

void mode_frame_powers(const RoomFootprint::ModeTerms& m, const SpectrogramGrid& g, const RoomRates& rates,
                       const RoomFrameSums& sums, std::size_t frames, double* rendered, double* added,
                       double* reverberant_part) {
  const double half_window = 0.5 * double(g.window);
  const double k = rates.k_per_sample[m.octave], x = 2.0 * (m.delta - k);
  const double dry = mode_dry_factor(m, rates);
  // The rendering's own power (a^2/2 over the window), scaled by dry; the reverberant part
  // sigma^2 (a^2/2) G (e^{-2 k i} - e^{-2 delta i}), G = 1 / (1 - e^{-x}) (i e^{-2 delta i} when x = 0).
  const double own = half_window * 0.5 * m.a2;
  const double room = half_window * m.own_share * rates.sigma2 * 0.5 * m.a2 * dry;
  const bool equal = std::abs(x) < 1e-9;
  const double G = equal ? 0.0 : 1.0 / -std::expm1(-x);
  double room_t = 1.0, mode_t = 1.0;  // e^{-2 k t0}, e^{-2 delta t0}
  for (std::size_t f = 0; f < frames; ++f, room_t *= sums.per_hop[m.octave], mode_t *= m.per_hop) {
    const double reverberant = equal ? mode_t * (double(f * g.hop) * m.window_sum + m.ramp_sum)
                                     : G * (room_t * sums.frame_sum[m.octave] - mode_t * m.window_sum);
    rendered[f] = own * mode_t * m.window_sum;
    added[f] = std::max((dry - 1.0) * rendered[f] + m.answer * room * reverberant,
                        (kMinAnsweredShare * dry - 1.0) * rendered[f]);
    if (reverberant_part) reverberant_part[f] = room * reverberant;
  }
}

double mode_dry_factor(const RoomFootprint::ModeTerms& m, const RoomRates& rates) {
  return dry_power_scale(rates, m.octave, m.delta) / m.rendered_scale * m.extra_power;
}

double mode_reverb_ratio(const RoomFootprint::ModeTerms& m, const RoomRates& rates) {
  const double k = rates.k_per_sample[m.octave];
  if (m.delta >= k) return 0.0;
  return m.own_share * rates.sigma2 / std::expm1(2.0 * (k - m.delta));
}

std::pair<double, double> mode_answer_range(const RoomFootprint::ModeTerms& m, const RoomRates& rates) {
  const double q = mode_reverb_ratio(m, rates);
  if (q <= 0.0) return {0.25, 3.0};
  const double r = std::sqrt(q);
  // |1 + h|^2 = 1 + answer q.
  const double lo = std::max(1.0 - 2.0 * r, 0.1), hi = 1.0 + 2.0 * r;
  return {(lo * lo - 1.0) / q, (hi * hi - 1.0) / q};
}

void add_room_power(BarkSpectrogram& spec, const SpectrogramGrid& g, const RoomGrid& rg, const RoomFootprint& fp,
                    const RoomRates& rates) {
  if (spec.frames == 0) return;
  const RoomFrameSums sums = room_frame_sums(g, rates);
  std::vector<double> rendered(spec.frames), added(spec.frames);
  for (const RoomFootprint::ModeTerms& m : fp.modes) {
    mode_frame_powers(m, g, rates, sums, spec.frames, rendered.data(), added.data());
    for (const auto& [b, l] : m.leakage) {
      double* column = spec.power.data() + b;
      for (std::size_t f = 0; f < spec.frames; ++f) column[f * spec.bands] += l * added[f];
    }
  }
  if (rates.sigma2 <= 0.0) return;
  const double half_window = 0.5 * double(g.window);
  std::array<double, kRoomBands> dry_scale{};  // the onsets' amplitudes scale as a slow mode's
  for (std::size_t o = 0; o < kRoomBands; ++o) dry_scale[o] = dry_power_scale(rates, o, 0.0) / fp.onset_scale[o];
  for (std::size_t b = 0; b < g.bands && b < fp.onset_gram.size(); ++b) {
    double energy = 0.0;
    for (std::size_t o = 0; o < kRoomBands; ++o)
      for (std::size_t p = 0; p < kRoomBands; ++p)
        energy += std::sqrt(dry_scale[o] * dry_scale[p]) * fp.onset_gram[b][o * kRoomBands + p];
    if (energy <= 0.0) continue;
    const std::size_t o = rg.band_octave[b];
    double level = half_window * rates.sigma2 * energy * sums.frame_sum[o];
    for (std::size_t f = 0; f < spec.frames; ++f, level *= sums.per_hop[o]) spec.at(f, b) += level;
  }
}

}  // namespace ms::audit
