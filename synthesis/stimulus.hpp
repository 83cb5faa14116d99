// Rendering a parameter set into a stimulus: drop modes at or above Nyquist (with a warning),
// run the resonator bank, apply the output level.
#pragma once
#include <string>
#include <vector>

#include "synthesis/audio_file.hpp"
#include "synthesis/paramset.hpp"

namespace ms {

struct RenderedStimulus {
  Audio audio;                        // mono
  std::vector<std::string> warnings;  // the parameter set's and the renderer's
  std::size_t modes_rendered = 0;
  double level_gain = 1.0;            // factor applied by the output level
};

// The model that will actually sound (modes below Nyquist); appends a warning when modes drop.
ModalModel audible_model(const ParamSet& p, std::vector<std::string>& warnings);

RenderedStimulus render_stimulus(const ParamSet& p);

// Throws InputError at the recipe's key when the rendered sound cannot be written in its format: a
// PCM format and a peak above full scale (at output.format, or `format_where` when the format came
// from elsewhere, e.g. --format), or samples that are not finite (at the set's file).
void check_writable(const ParamSet& p, const Audio& audio, const SourceLocation& format_where);

}  // namespace ms
