// Pi_psycho, loudness weights of modes, Pi_hybrid; see perceptual_metric.hpp.
#include "analysis/estimation/perceptual_metric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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

std::vector<FeaturePoint> loudness_weighted_features(const std::vector<Mode>& modes, const LoudnessImager& imager,
                                                     double db_spl_at_unit_power, std::size_t frames) {
  const double fs = imager.sample_rate_hz();
  const std::vector<double>& w = imager.window_samples();
  const std::size_t n = w.size();
  double w2 = 0.0;
  for (double v : w) w2 += v * v;
  const double hop_s = double(imager.hop()) / fs, centre_s = 0.5 * double(n) / fs;
  std::vector<FeaturePoint> points;
  points.reserve(modes.size());
  for (const Mode& m : modes) {
    FeaturePoint p{m.freq_hz, m.decay_per_s, 0.0};
    const std::size_t band = imager.band_of_hz(m.freq_hz);
    if (m.decay_per_s > 0.0 && m.freq_hz > 0.0 && m.freq_hz < 0.5 * fs && band < imager.bands() && m.amp != 0.0) {
      // Hann-weighted mean of e^{-2d(t - t_centre)} over one frame: the decay within the frame.
      double within = 0.0;
      for (std::size_t k = 0; k < n; ++k)
        within += w[k] * w[k] * std::exp(-2.0 * m.decay_per_s * (double(k) / fs - centre_s));
      const double first = 0.5 * m.amp * m.amp * within / w2 * std::exp(-2.0 * m.decay_per_s * centre_s);
      const double per_frame = std::exp(-2.0 * m.decay_per_s * hop_s);
      const ToneLoudness tone(iso226_parameters(imager.band_centre_hz(band)), db_spl_at_unit_power);
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

PerceptualScores PerceptualReference::compare(const std::vector<float>& y, const std::vector<Mode>& modes) const {
  PerceptualScores s;
  s.psycho = psycho(y);
  const auto other = loudness_weighted_features(modes, imager_, db_spl_at_unit_power_, sone_.frames);
  s.match = match_ratio_product(features_, other, options_.match);
  s.hybrid = hybrid_metric(s.psycho, s.match);
  return s;
}

}  // namespace ms
