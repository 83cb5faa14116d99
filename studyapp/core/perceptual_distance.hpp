// A cheap perceptual distance between two stimuli for the simulated listener: Bark-band (Zwicker)
// levels in dB over the first 200 ms in 20 ms frames and of the whole sound, compared as the RMS
// difference in dB over bands and frames (bands more than 60 dB below the louder sound's peak are
// floored there, so inaudible differences do not count).
#pragma once
#include <vector>

namespace ms {

struct PerceptualProfile {
  std::vector<double> level_db;  // frames x bands, row-major
  double centroid_bark = 0.0;    // loudness-weighted mean band of the whole sound
  double decay_s = 0.0;          // time for the broadband level to fall 30 dB below its peak
};

PerceptualProfile perceptual_profile(const std::vector<float>& samples, double sample_rate_hz);
double perceptual_distance_db(const PerceptualProfile& a, const PerceptualProfile& b);

}  // namespace ms
