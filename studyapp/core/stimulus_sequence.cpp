// Sequence stimuli: mixing the parts at their onsets and the recipe hash; see stimulus_sequence.hpp.
#include "studyapp/core/stimulus_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "synthesis/exact_number.hpp"
#include "synthesis/sha256.hpp"

namespace ms {

std::size_t onset_frame(double onset_s, double sample_rate_hz) {
  return std::size_t(std::llround(onset_s * sample_rate_hz));
}

std::vector<float> mix_sequence(const std::vector<SequenceStrike>& strikes, double sample_rate_hz,
                                const SourceLocation& where, const std::string& name) {
  std::size_t frames = 0;
  for (const SequenceStrike& s : strikes) frames = std::max(frames, onset_frame(s.onset_s, sample_rate_hz) + s.samples->size());
  if (double(frames) > kSequenceMaxS * sample_rate_hz) {
    char seconds[40];
    std::snprintf(seconds, sizeof seconds, "%.1f s, more than %.0f s", double(frames) / sample_rate_hz, kSequenceMaxS);
    throw InputError(where, "stimulus '" + name + "': the sequence would last " + seconds);
  }
  // Summed in double so that the result is the parts' exact sum rounded once.
  std::vector<double> sum(frames, 0.0);
  for (const SequenceStrike& s : strikes) {
    const double gain = std::pow(10.0, s.gain_db / 20.0);
    double* out = sum.data() + onset_frame(s.onset_s, sample_rate_hz);
    const std::vector<float>& x = *s.samples;
    for (std::size_t n = 0; n < x.size(); ++n) out[n] += gain * double(x[n]);
  }
  return std::vector<float>(sum.begin(), sum.end());
}

std::string sequence_hash(const std::vector<SequenceRecipePart>& parts, double sample_rate_hz) {
  std::string recipe = "sequence at " + exact_number(sample_rate_hz) + " Hz\n";
  for (const SequenceRecipePart& p : parts)
    recipe += "onset_s=" + exact_number(p.onset_s) + " gain_db=" + exact_number(p.gain_db) + " part=" + p.hash + "\n";
  return sha256_hex(recipe);
}

}  // namespace ms
