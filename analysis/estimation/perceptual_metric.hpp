// Ren et al.'s perceptual metrics (patent US 9,401,684 Sec. 5.2): the psychoacoustic image metric
// Pi_psycho (Eq. 19: squared difference of two loudness images, summed), the feature points of a set
// of modes weighted by their loudness (App. C), and the hybrid metric Pi_hybrid = Pi_psycho / |Pi_MRP|
// (Eq. 27) that the estimation of material parameters minimises.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/estimation/feature_match.hpp"
#include "analysis/estimation/loudness_image.hpp"
#include "synthesis/modal_model.hpp"

namespace ms {

// Eq. 19: sum over frames and bands of (a - b)^2 [sone^2]. Images of one grid (same bands); frames
// one image lacks count as silence (0 sone), so a sound that rings longer is charged for it.
// Throws std::invalid_argument when the band counts differ.
double psycho_distance(const BarkImage& a_sone, const BarkImage& b_sone);

// App. C: a mode's weight is its energy integrated over the loudness image, i.e. the loudness [sone]
// of the damped sinusoid alone summed over the frames of `frames` times the hop [s] (sone s). The
// mode's mean square in frame m is taken in closed form, amp^2/2 e^{-2 d t_m} times the Hann-weighted
// mean of e^{-2 d (t - t_m)} over the frame, all in the band holding its frequency; a mode at or
// above Nyquist, inaudible at this calibration, or without a positive decay weighs 0.
std::vector<FeaturePoint> loudness_weighted_features(const std::vector<Mode>& modes, const LoudnessImager& imager,
                                                     double db_spl_at_unit_power, std::size_t frames);

// Eq. 27: psycho / |product|; +infinity when nothing matches (product 0).
double hybrid_metric(double psycho, const MatchRatios& ratios);

struct PerceptualOptions {
  LoudnessImageOptions image;
  double playback_db_spl = 70.0;  // the reference's loudest image cell is played at this level
  FeatureMatchConstants match;
};

struct PerceptualScores {
  double psycho = 0.0;  // Pi_psycho [sone^2]
  MatchRatios match;    // R, R~ and Pi_MRP
  double hybrid = 0.0;  // Pi_hybrid
};

// The reference side (a recording and its extracted modes, both from its onset), computed once: its
// loudness image, the calibration it fixes, and its weighted feature points. compare() then costs one
// image of the other sound, its modes' weights and the match, which is what an estimation repeats.
class PerceptualReference {
 public:
  PerceptualReference(const std::vector<float>& samples, double sample_rate_hz, const std::vector<Mode>& modes,
                      const PerceptualOptions& options = {});

  // The other sound (same sample rate, from its onset) and its modes.
  PerceptualScores compare(const std::vector<float>& samples, const std::vector<Mode>& modes) const;
  // The same with white noise of standard deviation noise_sigma heard under the other sound, taken by
  // its expected power: each band's mean square gains noise_sigma^2 2 n_b / N (n_b the rfft bins of
  // band b, N the window), the cross terms averaging to 0. Unlike one seeded draw of noise, no
  // particular noise waveform is matched against the recording's own.
  PerceptualScores compare(const std::vector<float>& samples, const std::vector<Mode>& modes,
                           double noise_sigma) const;
  // Pi_psycho alone.
  double psycho(const std::vector<float>& samples) const;
  // The other sound's loudness image at the reference's calibration.
  BarkImage sone_image(const std::vector<float>& samples) const;

  const LoudnessImager& imager() const { return imager_; }
  double db_spl_at_unit_power() const { return db_spl_at_unit_power_; }
  const BarkImage& sone() const { return sone_; }
  const std::vector<FeaturePoint>& features() const { return features_; }

 private:
  PerceptualOptions options_;
  LoudnessImager imager_;
  double db_spl_at_unit_power_ = 0.0;
  BarkImage sone_;
  std::vector<FeaturePoint> features_;
};

}  // namespace ms
