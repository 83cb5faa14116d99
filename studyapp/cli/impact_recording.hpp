// One recorded impact as the perceptual commands (compare, estimate) read it: mono, checked (silent,
// clipped, too short and unreadable files are InputErrors naming the file), cut at its onset, and its
// modes extracted with the defaults of `modalstudy extract`.
#pragma once
#include <string>
#include <vector>

#include "synthesis/modal_model.hpp"

namespace ms::cli {

struct ImpactRecording {
  std::string path;
  double sample_rate_hz = 0.0;
  double onset_s = 0.0;
  std::vector<float> whole;    // mono, as recorded (the extractor finds its own onset)
  std::vector<float> samples;  // mono, from the onset
  std::vector<Mode> modes;     // extracted by extract_impact_modes, amplitudes at the onset
  double noise_sigma = 0.0;    // the extractor's white-noise standard deviation (full scale = 1)
};

// channel: 0-based, or -1 to mix to mono.
ImpactRecording load_impact_recording(const std::string& path, int channel);

// Fills r.modes; none above the noise floor is an InputError naming the file.
void extract_impact_modes(ImpactRecording& r);

}  // namespace ms::cli
