// Pi_psycho, loudness weights of modes, Pi_hybrid; see perceptual_metric.hpp.
#include "analysis/estimation/perceptual_metric.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "analysis/estimation/iso226_loudness.hpp"

namespace ms {

double psycho_distance(const BarkImage& a, const BarkImage& b) {
  if (a.bands != b.bands) throw std::invalid_argument("psycho_distance: images with different bands");
  double sum = 0.0;
  const std::size_t common = std::min(a.frames, b.frames) * a.bands;
  for (std::size_t i = 0; i < common; ++i) {
    const double d = a.cells[i] - b.cells[i];
    sum += d * d;
  }
  for (std::size_t i = common; i < a.cells.size(); ++i) sum += a.cells[i] * a.cells[i];
  for (std::size_t i = common; i < b.cells.size(); ++i) sum += b.cells[i] * b.cells[i];
  return sum;
}

namespace {

// sum_k w_k^2 e^{-r k} over a periodic Hann window w_k = (1 - cos(2 pi k / N)) / 2, in closed form:
// w^2 = 3/8 - cos(theta k)/2 + cos(2 theta k)/8 with theta = 2 pi / N, and each term a geometric sum
// sum_k (e^{-r + i j theta})^k = (1 - e^{-r N}) / (1 - e^{-r + i j theta}) (e^{i j theta N} = 1).
double hann_squared_decay_sum(const std::vector<double>& w, double r) {
  const std::size_t n = w.size();
  if (!(r > 1e-9)) {  // no decay within the frame (or too little for the closed form to resolve)
    double s = 0.0;
    for (std::size_t k = 0; k < n; ++k) s += w[k] * w[k] * std::exp(-r * double(k));
    return s;
  }
  const double one_minus_rn = -std::expm1(-r * double(n));
  const double theta = 2.0 * std::numbers::pi / double(n);
  auto term = [&](double j) {
    if (j == 0.0) return one_minus_rn / -std::expm1(-r);
    const std::complex<double> q = std::exp(std::complex<double>(-r, j * theta));
    return std::real(one_minus_rn / (1.0 - q));
  };
  return 0.375 * term(0) - 0.5 * term(1) + 0.125 * term(2);
}

}  // namespace

std::vector<FeaturePoint> loudness_weighted_features(const std::vector<Mode>& modes, const LoudnessImager& imager,
                                                     double db_spl_at_unit_power, std::size_t frames) {
  const double fs = imager.sample_rate_hz();
  const std::vector<double>& w = imager.window_samples();
  double w2 = 0.0;
  for (double v : w) w2 += v * v;
  const double hop_s = double(imager.hop()) / fs;
  std::vector<FeaturePoint> points;
  points.reserve(modes.size());
  // One contour per band, not per mode: a plate's candidate has hundreds of modes in a few dozen bands.
  std::vector<ToneLoudness> tone_of_band;
  tone_of_band.reserve(imager.bands());
  for (std::size_t b = 0; b < imager.bands(); ++b)
    tone_of_band.emplace_back(iso226_parameters(imager.band_centre_hz(b)), db_spl_at_unit_power);
  for (const Mode& m : modes) {
    FeaturePoint p{m.freq_hz, m.decay_per_s, 0.0};
    const std::size_t band = imager.band_of_hz(m.freq_hz);
    if (m.decay_per_s > 0.0 && m.freq_hz > 0.0 && m.freq_hz < 0.5 * fs && band < imager.bands() && m.amp != 0.0) {
      // The first frame's mean square: the Hann-weighted mean of amp^2/2 e^{-2 d t} over it.
      const double first = 0.5 * m.amp * m.amp * hann_squared_decay_sum(w, 2.0 * m.decay_per_s / fs) / w2;
      const double per_frame = std::exp(-2.0 * m.decay_per_s * hop_s);
      const ToneLoudness& tone = tone_of_band[band];
      double mean_sq = first, sum = 0.0;
      for (std::size_t f = 0; f < frames; ++f, mean_sq *= per_frame) {
        const double s = tone.sone(mean_sq);
        if (s <= 0.0) break;  // the level only falls from here
        sum += s;
      }
      p.weight = sum * hop_s;
    }
    points.push_back(p);
  }
  return points;
}

double hybrid_metric(double psycho, const MatchRatios& r) {
  const double mrp = std::abs(r.product);
  return mrp > 0.0 ? psycho / mrp : std::numeric_limits<double>::infinity();
}

PerceptualReference::PerceptualReference(const std::vector<float>& x, double fs, const std::vector<Mode>& modes,
                                         const PerceptualOptions& o)
    : options_(o), imager_(fs, o.image) {
  const BarkImage power = imager_.power(x);
  db_spl_at_unit_power_ = db_spl_at_unit_power_for_peak(power, o.playback_db_spl);
  sone_ = imager_.loudness(power, db_spl_at_unit_power_);
  features_ = loudness_weighted_features(modes, imager_, db_spl_at_unit_power_, sone_.frames);
}

BarkImage PerceptualReference::sone_image(const std::vector<float>& y) const {
  return imager_.loudness(imager_.power(y), db_spl_at_unit_power_);
}

double PerceptualReference::psycho(const std::vector<float>& y) const { return psycho_distance(sone_, sone_image(y)); }

PerceptualScores PerceptualReference::compare(const std::vector<float>& y, const std::vector<Mode>& modes,
                                              double noise_sigma) const {
  BarkImage power = imager_.power(y);
  if (noise_sigma > 0.0) {
    std::vector<double> band_noise(power.bands, 0.0);
    const std::size_t n = imager_.window();
    const double fs = imager_.sample_rate_hz();
    for (std::size_t k = 1; k <= n / 2; ++k) {
      const std::size_t b = std::min(imager_.band_of_hz(double(k) * fs / double(n)), power.bands - 1);
      band_noise[b] += (k == n / 2 ? 0.5 : 1.0) * 2.0 * noise_sigma * noise_sigma / double(n);
    }
    for (std::size_t m = 0; m < power.frames; ++m)
      for (std::size_t b = 0; b < power.bands; ++b) power.at(m, b) += band_noise[b];
  }
  PerceptualScores s;
  s.psycho = psycho_distance(sone_, imager_.loudness(power, db_spl_at_unit_power_));
  const auto other = loudness_weighted_features(modes, imager_, db_spl_at_unit_power_, sone_.frames);
  s.match = match_ratio_product(features_, other, options_.match);
  s.hybrid = hybrid_metric(s.psycho, s.match);
  return s;
}

PerceptualScores PerceptualReference::compare(const std::vector<float>& y, const std::vector<Mode>& modes) const {
  return compare(y, modes, 0.0);  // no noise added: the loudness image of y itself
}

}  // namespace ms
