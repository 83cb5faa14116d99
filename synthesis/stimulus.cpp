#include "synthesis/stimulus.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "synthesis/input_error.hpp"

#include "synthesis/bandpass_bank.hpp"
#include "synthesis/residual_transfer.hpp"
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
  // The band-pass bank leaves out the modes that cannot sound itself, keeping each mode's Q beside it.
  out.audio.samples = p.renderer == Renderer::bandpass
                          ? render_bandpass(p.model, p.bandpass_q, p.excitation.gain, p.bandpass_clip,
                                            p.sample_rate_hz, frames)
                          : render_bank(model, p.excitation, p.sample_rate_hz, frames);
  if (const auto& r = p.residual.spectrogram)
    add_transferred_residual(out.audio.samples, *r, heard_modes(model.modes, p.excitation), p.sample_rate_hz,
                             p.residual.gain_db, p.residual.seed);
  apply_room(out.audio.samples, p.sample_rate_hz, p.room);
  add_reverb_and_transient(out.audio.samples, p.sample_rate_hz, p.reverb, p.transient);
  add_background_noise(out.audio.samples, p.noise);
  out.level_gain = level_gain(out.audio.samples, p.sample_rate_hz, p.level);
  if (out.level_gain != 1.0)
    for (float& v : out.audio.samples) v = float(v * out.level_gain);
  return out;
}

void check_writable(const ParamSet& p, const Audio& audio, const SourceLocation& format_where) {
  float peak = 0.0f;
  for (float v : audio.samples) {
    if (!std::isfinite(v))
      throw InputError(SourceLocation{p.source, 0, 0},
                       "the rendered sound has NaN or infinite samples (an amplitude, gain or level far too large?)");
    peak = std::max(peak, std::abs(v));
  }
  if (p.format != SampleFormat::float32 && peak > 1.0f) {
    char db[32];
    std::snprintf(db, sizeof db, "%+.1f", 20.0 * std::log10(double(peak)));
    throw InputError(format_where, "output.format: " + to_string(p.format) + " cannot hold the rendered peak of " +
                                       db + " dBFS (use float32, or a level that normalizes to at most 0 dBFS)");
  }
}

}  // namespace ms
