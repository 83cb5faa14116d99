// Sub-band ESPRIT + joint refinement + noise/hum clean-up; see feature_extraction.hpp.
#include "analysis/extraction/feature_extraction.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <complex>
#include <numbers>

#include "analysis/extraction/damped_fit.hpp"
#include "analysis/extraction/damped_pursuit.hpp"
#include "analysis/extraction/esprit.hpp"
#include "analysis/extraction/mode_precision.hpp"
#include "analysis/extraction/noise_envelope.hpp"
#include "analysis/extraction/noise_floor.hpp"
#include "analysis/extraction/onset.hpp"
#include "analysis/extraction/subband.hpp"

namespace ms {
namespace {

using cd = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct Band {
  double lo_hz, hi_hz;
};

// Narrow bands: 100 Hz at the bottom (crowded, with mirror images below 0 Hz), growing by half the
// lower edge up to the nominal width.
std::vector<Band> narrow_layout(double top_hz, double width_hz) {
  std::vector<Band> bands;
  for (double lo = 0.0; lo < top_hz;) {
    const double w = std::clamp(0.5 * lo, std::min(100.0, width_hz), width_hz);
    bands.push_back({lo, std::min(lo + w, top_hz)});
    lo += w;
  }
  return bands;
}

// Wide bands: 400 Hz at the bottom (a short window still spans a few periods), doubling up to the
// nominal width.
std::vector<Band> wide_layout(double top_hz, double width_hz) {
  std::vector<Band> bands;
  for (double lo = 0.0; lo < top_hz;) {
    const double w = std::clamp(lo, std::min(400.0, width_hz), width_hz);
    bands.push_back({lo, std::min(lo + w, top_hz)});
    lo += w;
  }
  return bands;
}

// Under a room tail, ESPRIT's noise is at least this times a band's median eigenvalue (a generated
// room of RT60 0.8 s, DRR +3 dB: 92 components per 2 s strike instead of 203, in 0.26 s instead of
// 1.3 s, every mode still found; a factor of 2 left twice the components, 16 lost modes).
constexpr double kRoomTailOwnNoise = 4.0;

// ESPRIT on every band with energy above the noise; poles whose frequency lies in the band's core.
void scan_bands(SubbandSplitter& split, const std::vector<Band>& bands, double fs, double max_s,
                double min_freq_hz, double hum_decay_per_s, double threshold_factor, const NoiseEnvelope& tail,
                std::vector<DampedComponent>& found) {
  for (const Band& b : bands) {
    // A band whose loudest bin is within ~13 dB of the noise has nothing ESPRIT could find there.
    if (split.peak_to_noise(b.lo_hz, b.hi_hz) < 20.0) continue;
    const double core = b.hi_hz - b.lo_hz;
    BandSignal sig = split.band(0.5 * (b.lo_hz + b.hi_hz), core, core);
    std::size_t end = std::min(sig.samples.size(), std::size_t(max_s * sig.rate_hz));
    if (end > 2 * sig.settle) end -= sig.settle;
    // Stop where the band has decayed into the noise (blocks of 16 samples, 3x the noise variance,
    // which a room tail raises for a while).
    constexpr std::size_t kBlock = 16;
    std::size_t last = sig.settle;
    for (std::size_t j = sig.settle; j + kBlock <= end; j += kBlock) {
      double p = 0.0;
      for (std::size_t i = j; i < j + kBlock; ++i) p += std::norm(sig.samples[i]);
      const double louder = tail.at(std::size_t(double(j) * fs / sig.rate_hz)) / tail.floor_variance;
      if (p > 3.0 * double(kBlock) * sig.noise_variance * std::max(1.0, louder)) last = j + kBlock;
    }
    end = std::min(end, last + 4 * kBlock);
    if (end <= sig.settle + 24) continue;
    const std::size_t length = end - sig.settle;
    EspritOptions eo;
    eo.window = std::clamp<std::size_t>(length / 3, 8, 64);
    eo.threshold_factor = threshold_factor;
    eo.max_order = eo.window - 4;
    // The covariance ESPRIT orders by averages the noise over the span: under a room tail, its mean.
    double mean_louder = 1.0;
    if (!tail.flat()) {
      double sum = 0.0;
      for (std::size_t j = sig.settle; j < end; ++j) sum += tail.at(std::size_t(double(j) * fs / sig.rate_hz));
      mean_louder = std::max(1.0, sum / double(length) / tail.floor_variance);
    }
    eo.noise_power = sig.noise_power * mean_louder;
    // A room's tail is coloured like the modes (each mode's own reverberation surrounds it): judged
    // against the broadband level, a band fills with poles fitted to it (~10x the modes, 5x the time).
    if (!tail.flat()) eo.own_noise_factor = kRoomTailOwnNoise;
    const auto poles = esprit(sig.samples.data() + sig.settle, length, eo);
    for (const cd& z : poles) {
      if (std::abs(z) <= 0.0) continue;
      const double f = sig.center_hz + std::arg(z) * sig.rate_hz / kTwoPi;
      const double d = -std::log(std::abs(z)) * sig.rate_hz;
      // Stationary lines (hum) are dropped here already: they are not part of the impact.
      if (f < b.lo_hz || f >= b.hi_hz || f < min_freq_hz || d > 0.25 * sig.rate_hz || d < hum_decay_per_s)
        continue;
      found.push_back({cd(-std::max(d, 0.0), kTwoPi * f) / fs, cd(0.0, 0.0)});
    }
  }
}

// Pairs of components, one of them fast, that largely cancel each other (their sum carries under a
// quarter of their energies) are an ill-posed fit of crowded heavily damped modes, not two modes:
// both go, and the pursuit rebuilds that region from the residual.
void drop_cancelling(std::vector<DampedComponent>& c, std::size_t frames, double min_decay) {
  const std::size_t K = c.size();
  std::vector<double> e(K);
  for (std::size_t k = 0; k < K; ++k) e[k] = component_energy(c[k], 0, frames);
  std::vector<bool> bad(K, false);
  for (std::size_t j = 0; j < K; ++j)
    for (std::size_t k = j + 1; k < K; ++k) {
      if (-c[j].s.real() < min_decay && -c[k].s.real() < min_decay) continue;
      const cd tp = weighted_geometric_sum(0, c[j].s + c[k].s, frames);
      const cd tm = weighted_geometric_sum(0, c[j].s + std::conj(c[k].s), frames);
      const double cross = 0.5 * (c[j].b * c[k].b * tp + c[j].b * std::conj(c[k].b) * tm).real();
      if (e[j] + e[k] + 2.0 * cross < 0.25 * (e[j] + e[k])) bad[j] = bad[k] = true;
    }
  std::size_t k = 0;
  std::erase_if(c, [&](const DampedComponent&) { return bad[k++]; });
}

// Poles closer than the estimation noise describe one mode: keep the stronger.
void merge_duplicates(std::vector<DampedComponent>& c, double fs) {
  std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return std::abs(a.b) > std::abs(b.b); });
  std::vector<DampedComponent> kept;
  for (const auto& x : c) {
    bool dup = false;
    for (const auto& k : kept) {
      const double df = std::abs(x.s.imag() - k.s.imag()) * fs / kTwoPi;
      const double dd = std::abs(x.s.real() - k.s.real()) * fs;
      const double dmax = std::max(-x.s.real(), -k.s.real()) * fs;
      if (df < 0.2 + 0.02 * dmax / kTwoPi && dd < 0.25 * dmax + 0.2) dup = true;
    }
    if (!dup) kept.push_back(x);
  }
  c = std::move(kept);
}

// A component starting far above the recording's own peak is not a mode: it is one of a group of
// crowded fast components that cancel each other (an ill-conditioned joint fit; drop_cancelling only
// sees pairs). A real impact's modes start roughly in phase, so none exceeds the peak by this much.
constexpr double kMaxAmpOverPeak = 3.0;

bool overshoots(const DampedComponent& c, double peak) { return std::abs(c.b) > kMaxAmpOverPeak * peak; }

// Attack blocks whose residual stands this far above its later level are attack noise (10 dB: a
// room tail of RT60 0.2 s falls 3 dB per 10 ms, a clean strike's residual stays within 3 dB).
constexpr double kAttackNoiseRatio = 10.0;

}  // namespace

std::optional<std::string> recording_problem(const std::vector<float>& samples, double sample_rate_hz) {
  if (!(sample_rate_hz > 0.0)) return "sample rate is not positive";
  if (double(samples.size()) < 0.05 * sample_rate_hz)
    return "too short: " + std::to_string(samples.size()) + " frames, an impact needs at least 50 ms";
  float top = 0.0f, bottom = 0.0f;
  for (float v : samples) {
    top = std::max(top, v);
    bottom = std::min(bottom, v);
  }
  if (top == 0.0f && bottom == 0.0f) return "silent: every sample is zero";
  // A constant (DC) signal sits at its own extremes everywhere without having been clipped.
  if (std::all_of(samples.begin(), samples.end(), [&](float v) { return v == samples.front(); })) {
    char value[32];
    std::snprintf(value, sizeof value, "%.6g", double(samples.front()));
    return "constant: every sample is " + std::string(value) + " (no impact in it)";
  }
  // Clipping: runs of 3+ consecutive samples pinned at either rail, over 0.1 % of the recording.
  std::size_t pinned = 0, run = 0;
  float rail_prev = 0.0f;
  for (float v : samples) {
    const float rail = v >= top * (1.0f - 2e-7f) && top > 0.0f      ? 1.0f
                       : v <= bottom * (1.0f - 2e-7f) && bottom < 0.0f ? -1.0f
                                                                      : 0.0f;
    run = (rail != 0.0f && rail == rail_prev) ? run + 1 : (rail != 0.0f ? 1 : 0);
    if (run == 3) pinned += 3;
    else if (run > 3) ++pinned;
    rail_prev = rail;
  }
  if (double(pinned) > 1e-3 * double(samples.size()) && pinned >= 8)
    return "clipped: " + std::to_string(pinned) + " samples are pinned at full scale";
  return std::nullopt;
}

namespace {

// The modes of x from sample `start` on (steps 3-7 of the header), with the signal they were fitted to.
struct ModalFit {
  std::vector<double> signal;        // x from start, at most max_duration_s
  std::vector<DampedComponent> comps;
  NoiseEnvelope noise;               // the noise the fit assumed, per sample of signal
  double sigma = 0.0;                // white-noise std the fit assumed (floored on noiseless input)
  NoiseProfile profile;              // coloured floor per band (empty when white)
};

// What every step of one fit shares: the signal, the noise it is judged against and the options.
struct FitContext {
  const std::vector<double>& signal;
  double fs;
  std::size_t frames;        // samples in signal
  std::size_t early;         // samples the wide bands scan
  double sigma;              // white-noise std (floored on noiseless input)
  double noise_energy;       // sigma^2
  double peak;               // the signal's largest magnitude
  double top_hz;             // highest frequency scanned
  const NoiseProfile& noise;
  const NoiseEnvelope& tail;
  const ExtractOptions& options;
  RefineOptions refine;
};

// Under a tail a component is judged by what it explains with the tail's weights, which needs the
// residual of the fit it belongs to (empty without a tail: then its energy alone decides).
std::vector<double> residual_of(const FitContext& f, const std::vector<double>& signal,
                                const std::vector<DampedComponent>& c) {
  return f.tail.flat() ? std::vector<double>{} : subtract_components(signal, c, signal.size());
}

// Per component: does it stand min_snr_db above the noise of its band (and, under a tail, does its
// weighted fit explain that much)?
std::vector<bool> audible(const FitContext& f, const std::vector<DampedComponent>& c,
                          const std::vector<double>& residual) {
  const std::vector<double> gains = residual.empty() ? std::vector<double>{} : f.tail.weighted_fit_gains(residual, c);
  std::vector<bool> out(c.size());
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double var = std::max(f.noise_energy, f.noise.variance_at(c[k].s.imag() * f.fs / kTwoPi));
    double snr = component_energy(c[k], 0, f.frames) / var;
    if (!gains.empty()) snr = std::min(snr, gains[k]);
    out[k] = 10.0 * std::log10(snr) >= f.options.min_snr_db;
  }
  return out;
}

// Candidates under the noise go at once; at most kMaxCandidates (strongest) survive a scan, which
// bounds the joint fit on pathological input (e.g. dense stationary tones).
void keep_audible(const FitContext& f, const std::vector<double>& signal, std::vector<DampedComponent>& c) {
  constexpr std::size_t kMaxCandidates = 240;
  const std::vector<bool> keep = audible(f, c, residual_of(f, signal, c));
  std::size_t k = 0;
  std::erase_if(c, [&](const DampedComponent&) { return !keep[k++]; });
  if (c.size() > kMaxCandidates) {
    std::sort(c.begin(), c.end(), [&](const auto& a, const auto& b) {
      return component_energy(a, 0, f.frames) > component_energy(b, 0, f.frames);
    });
    c.resize(kMaxCandidates);
  }
}

// Narrow bands over the whole duration (slow and moderately damped modes), then wide bands over
// the early part (fast modes the narrow masks' kernels hide), each on what is still unexplained.
void scan(const FitContext& f, const std::vector<double>& signal, std::vector<DampedComponent>& found) {
  const ExtractOptions& o = f.options;
  const std::size_t before = found.size();
  {
    SubbandSplitter split(signal, f.fs, f.sigma, &f.noise);
    scan_bands(split, narrow_layout(f.top_hz, o.narrow_band_hz), f.fs, o.max_duration_s, o.min_freq_hz,
               o.hum_decay_per_s, 4.0, f.tail, found);
  }
  std::vector<DampedComponent> with_slow(found.begin() + std::ptrdiff_t(before), found.end());
  fit_amplitudes(signal, with_slow);
  keep_audible(f, signal, with_slow);
  found.resize(before);
  found.insert(found.end(), with_slow.begin(), with_slow.end());
  const std::vector<double> rest = subtract_components(signal, with_slow, f.early);
  std::vector<DampedComponent> fast;
  SubbandSplitter split(rest, f.fs, f.sigma, &f.noise);
  scan_bands(split, wide_layout(f.top_hz, o.wide_band_hz), f.fs, o.wide_window_s, o.min_freq_hz, o.hum_decay_per_s,
             o.fast_threshold_factor, f.tail, fast);
  std::erase_if(fast, [&](const DampedComponent& c) { return -c.s.real() * f.fs < o.fast_decay_per_s; });
  fit_amplitudes(rest, fast);
  keep_audible(f, rest, fast);
  found.insert(found.end(), fast.begin(), fast.end());
}

// Greedy pursuit on the residual of the joint fit (replaces a second sub-band scan: it finds the
// crowded, heavily damped modes the bands miss, at a fraction of the cost).
PursuitOptions pursuit_options(const FitContext& f) {
  PursuitOptions po;
  po.min_freq_hz = f.options.min_freq_hz;
  po.max_freq_hz = f.top_hz;
  po.noise_variance = f.noise_energy;
  po.noise = &f.noise;
  po.tail = &f.tail;
  po.max_atoms = f.options.pursuit_atoms;
  return po;
}

// Hum, contact transients, out-of-range or overshooting poles, and what the noise hides.
void drop_unfit(const FitContext& f, std::vector<DampedComponent>& c) {
  const ExtractOptions& o = f.options;
  const std::vector<bool> heard = audible(f, c, residual_of(f, f.signal, c));
  std::size_t k = 0;
  std::erase_if(c, [&](const DampedComponent& m) {
    const double d = -m.s.real() * f.fs, freq = m.s.imag() * f.fs / kTwoPi;
    const bool kept = heard[k++];
    if (d < o.hum_decay_per_s || d > o.max_decay_per_s || freq < o.min_freq_hz || freq >= 0.5 * f.fs) return true;
    return overshoots(m, f.peak) || !kept;
  });
}

// The unfit go twice (between them the poles are refined, after them the amplitudes re-solved);
// amplitudes re-solved on fewer poles can still blow up where a cancelling group remains.
void clean_up(const FitContext& f, std::vector<DampedComponent>& comps) {
  for (int pass = 0; pass < 2; ++pass) {
    drop_unfit(f, comps);
    if (pass == 0) refine_poles(f.signal, comps, f.refine);
    else fit_amplitudes(f.signal, comps);
  }
  if (std::erase_if(comps, [&](const DampedComponent& c) { return overshoots(c, f.peak); }) > 0)
    fit_amplitudes(f.signal, comps);
}

// Second start for the crowded low band (optional, ~70 % more time): the joint fit settles in a
// local minimum when heavily damped low modes overlap (ESPRIT's bands merge them first). Rebuild
// that band from scratch by pursuit against everything else, refit all, and keep whichever start
// explains the recording better after the Bayesian information criterion's price per mode
// (4 ln N noise variances).
void restart_low_band(const FitContext& f, const PursuitOptions& po, std::vector<DampedComponent>& comps) {
  constexpr double kLowBandHz = 700.0, kLowMinDecay = 20.0;
  std::vector<DampedComponent> alt;
  for (const auto& c : comps)
    if (c.s.imag() * f.fs / kTwoPi >= kLowBandHz || -c.s.real() * f.fs < kLowMinDecay) alt.push_back(c);
  const std::size_t low = comps.size() - alt.size();
  if (low == 0) return;
  const double price = 4.0 * std::log(double(f.frames)) * f.noise_energy;
  auto cost = [&](const std::vector<DampedComponent>& all) {
    double e = 0.0;
    for (double v : subtract_components(f.signal, all, f.frames)) e += v * v;
    return e + price * double(all.size());
  };
  PursuitOptions band = po;
  band.max_freq_hz = kLowBandHz;
  band.max_atoms = int(low) + 4;
  damped_pursuit(f.signal, f.fs, alt, band);
  refine_poles(f.signal, alt, f.refine);
  drop_unfit(f, alt);
  fit_amplitudes(f.signal, alt);
  if (cost(alt) < cost(comps)) comps = std::move(alt);
}

ModalFit fit_modes(const std::vector<double>& x, double fs, std::size_t start, double noise_sigma,
                   const ExtractOptions& options) {
  ModalFit fit;
  start = std::min(start, x.size());
  const std::size_t frames = std::min(x.size() - start, std::size_t(options.max_duration_s * fs));
  fit.signal.assign(x.begin() + std::ptrdiff_t(start), x.begin() + std::ptrdiff_t(start + frames));
  const std::vector<double>& s = fit.signal;
  // A floor keeps the order selection sane on noiseless (synthetic) input.
  double peak = 0.0;
  for (double v : s) peak = std::max(peak, std::abs(v));
  fit.sigma = std::max(noise_sigma, std::pow(10.0, -options.max_dynamic_range_db / 20.0) * peak);
  const double noise_energy = fit.sigma * fit.sigma;
  // Coloured noise: per-band levels from the recording's tail (noise_floor.hpp).
  fit.profile = estimate_noise_profile(x, fs, fit.sigma);
  // A room tail: noise that decays after the strike (noise_envelope.hpp).
  fit.noise = options.room_tail ? estimate_noise_envelope(s, fs, noise_energy) : NoiseEnvelope{0, {}, noise_energy};
  RefineOptions ro;
  ro.max_iterations = options.refine_iterations;
  const FitContext f{.signal = s,
                     .fs = fs,
                     .frames = frames,
                     .early = std::min(frames, std::size_t(options.wide_window_s * fs)),
                     .sigma = fit.sigma,
                     .noise_energy = noise_energy,
                     .peak = peak,
                     .top_hz = 0.49 * fs,
                     .noise = fit.profile,
                     .tail = fit.noise,
                     .options = options,
                     .refine = ro};
  std::vector<DampedComponent>& comps = fit.comps;
  scan(f, s, comps);
  refine_poles(s, comps, ro);
  merge_duplicates(comps, fs);
  drop_cancelling(comps, frames, options.fast_decay_per_s / fs);
  std::erase_if(comps, [&](const DampedComponent& c) { return overshoots(c, peak); });
  const PursuitOptions po = pursuit_options(f);
  damped_pursuit(s, fs, comps, po);
  clean_up(f, comps);
  if (options.low_band_restart) restart_low_band(f, po, comps);
  return fit;
}

// Attack noise the modes cannot explain (a residual burst of the strike, a long contact): the span of
// blocks of ~1.5 ms at the start where the fit's residual, relative to the noise it expected, stands
// 10 dB above its own level 20-60 ms later; 0 when none does. Those samples are not modal: the fit
// should start after them.
std::size_t attack_noise_span(const ModalFit& fit, double fs, double max_skip_s) {
  const std::size_t block = std::max<std::size_t>(8, std::size_t(std::lround(1.45e-3 * fs)));
  const std::size_t blocks = std::min(fit.signal.size(), std::size_t(0.06 * fs)) / block;
  const std::size_t late = std::size_t(0.02 * fs) / block;
  if (blocks < late + 4) return 0;
  const std::vector<double> r = subtract_components(fit.signal, fit.comps, blocks * block);
  std::vector<double> excess(blocks);
  // The noise envelope's first frame takes in a burst too: the expected noise is read from 20 ms on
  // (a room tail of RT60 0.2 s is 6 dB louder before, under the 10 dB this looks for).
  const std::size_t from = std::size_t(0.02 * fs);
  for (std::size_t k = 0; k < blocks; ++k) {
    double e = 0.0, expected = 0.0;
    for (std::size_t n = k * block; n < (k + 1) * block; ++n) {
      e += r[n] * r[n];
      expected += fit.noise.at(std::max(n, from));
    }
    excess[k] = e / std::max(expected, 1e-300);
  }
  std::vector<double> later(excess.begin() + std::ptrdiff_t(late), excess.end());
  std::nth_element(later.begin(), later.begin() + std::ptrdiff_t(later.size() / 2), later.end());
  const double level = later[later.size() / 2];
  std::size_t span = 0;
  for (std::size_t k = 0; k < late && double(k * block) < max_skip_s * fs; ++k)
    if (excess[k] > kAttackNoiseRatio * level) span = (k + 1) * block;
  return span;
}

}  // namespace

ExtractedFeatures extract_features(const std::vector<float>& samples, double fs,
                                   const ExtractOptions& options) {
  ExtractedFeatures out;
  out.sample_rate_hz = fs;
  std::vector<double> x(samples.begin(), samples.end());
  out.noise_sigma = estimate_noise_sigma(x);
  out.noise_floor_db = noise_floor_db(out.noise_sigma);
  const std::size_t onset = find_onset(x, out.noise_sigma);
  out.onset_s = double(std::min(onset, x.size())) / fs;
  if (onset + std::size_t(0.01 * fs) >= x.size()) return out;
  std::size_t skip = std::size_t(std::llround(options.skip_contact_s * fs));
  ModalFit fit = fit_modes(x, fs, onset + skip, out.noise_sigma, options);
  // Noise at the attack that the modes cannot explain: start the fit after it (twice at most: a
  // fit freed of one burst's pseudo-modes can show the burst's remainder).
  for (int round = 0; round < 2 && options.max_attack_skip_s > 0.0; ++round) {
    const std::size_t more = attack_noise_span(fit, fs, options.max_attack_skip_s - double(skip) / fs);
    if (more == 0) break;
    skip += more;
    fit = fit_modes(x, fs, onset + skip, out.noise_sigma, options);
  }
  out.attack_skip_s = double(skip) / fs;
  // Error bars at the fitted values, before the amplitudes move to the onset (the bound does that).
  const std::vector<ModePrecision> precision =
      mode_precision(fit.comps, fit.signal.size(), fs, fit.sigma, double(skip));
  // The same bound at the onset: a fast component fitted after a long skip and carried back to the
  // onset can start orders of magnitude above anything recorded (e^(d skip)); its amplitude there
  // is not measured, and it is no mode.
  double recorded_peak = 0.0;
  for (std::size_t n = onset; n < x.size(); ++n) recorded_peak = std::max(recorded_peak, std::abs(double(x[n])));
  std::vector<std::pair<Mode, ModePrecision>> found;
  for (std::size_t k = 0; k < fit.comps.size(); ++k) {
    DampedComponent& c = fit.comps[k];
    c.b *= std::exp(-c.s * double(skip));  // amplitude at the onset, not at the end of the contact
    if (overshoots(c, recorded_peak)) continue;
    Mode m;
    m.freq_hz = c.s.imag() * fs / kTwoPi;
    m.decay_per_s = -c.s.real() * fs;
    m.amp = std::abs(c.b);
    m.phase_rad = std::remainder(std::arg(c.b) + 0.5 * std::numbers::pi, kTwoPi);
    // Under a coloured floor the mode's own band is what it is measured against; under a room tail,
    // the tail over the samples that fix each parameter.
    const double band = fit.profile.variance_at(m.freq_hz), white = fit.sigma * fit.sigma;
    auto louder = [&](int power) {
      const double seen = std::max(band, fit.noise.variance_seen(-c.s.real(), fit.signal.size(), power));
      return std::sqrt(std::max(1.0, seen / white));
    };
    ModePrecision p = precision[k];
    const double late = louder(2);
    p.freq_sd_hz *= late;
    p.decay_sd_per_s *= late;
    p.amp_sd *= louder(0);
    found.emplace_back(m, p);
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first.freq_hz < b.first.freq_hz; });
  for (const auto& [m, p] : found) {
    out.modes.push_back(m);
    out.precision.push_back(p);
  }
  return out;
}

}  // namespace ms
