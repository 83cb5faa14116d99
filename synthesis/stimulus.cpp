#include "synthesis/stimulus.hpp"

#include <cmath>

#include "synthesis/resonator_bank.hpp"

namespace ms {

ModalModel audible_model(const ParamSet& p, std::vector<std::string>& warnings) {
  ModalModel model = p.model;
  const std::size_t dropped = drop_modes_at_or_above(model, 0.5 * p.sample_rate_hz);
  if (dropped > 0)
    warnings.push_back(std::to_string(dropped) + " mode(s) at or above Nyquist (" +
                       std::to_string(std::lround(0.5 * p.sample_rate_hz)) + " Hz) dropped");
  return model;
}

RenderedStimulus render_stimulus(const ParamSet& p) {
  RenderedStimulus out;
  out.warnings = p.warnings;
  const ModalModel model = audible_model(p, out.warnings);
  out.modes_rendered = model.modes.size();
  const std::size_t frames = std::size_t(std::llround(p.duration_s * p.sample_rate_hz));
  out.audio.sample_rate_hz = p.sample_rate_hz;
  out.audio.channels = 1;
  out.audio.samples = render_bank(model, p.excitation, p.sample_rate_hz, frames);
  add_reverb_and_transient(out.audio.samples, p.sample_rate_hz, p.reverb, p.transient);
  add_background_noise(out.audio.samples, p.noise);
  out.level_gain = level_gain(out.audio.samples, p.sample_rate_hz, p.level);
  if (out.level_gain != 1.0)
    for (float& v : out.audio.samples) v = float(v * out.level_gain);
  return out;
}

}  // namespace ms
