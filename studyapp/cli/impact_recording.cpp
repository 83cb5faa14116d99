#include "studyapp/cli/impact_recording.hpp"

#include "analysis/extraction/feature_extraction.hpp"
#include "analysis/extraction/noise_floor.hpp"
#include "analysis/extraction/onset.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms::cli {

ImpactRecording load_impact_recording(const std::string& path, int channel) {
  const Audio audio = read_audio(path);
  if (channel >= audio.channels)
    throw InputError(SourceLocation{path, 0, 0}, "--channel " + std::to_string(channel) + " but the file has " +
                                                     std::to_string(audio.channels) + " channel(s)");
  std::vector<float> x = mono(audio, channel);
  if (auto problem = recording_problem(x, audio.sample_rate_hz)) throw InputError(SourceLocation{path, 0, 0}, *problem);
  ImpactRecording r;
  r.path = path;
  r.sample_rate_hz = audio.sample_rate_hz;
  const std::vector<double> xd(x.begin(), x.end());
  const std::size_t onset = find_onset(xd, estimate_noise_sigma(xd));
  if (onset >= x.size()) throw InputError(SourceLocation{path, 0, 0}, "no impact found (no onset above the noise)");
  r.onset_s = double(onset) / audio.sample_rate_hz;
  r.samples.assign(x.begin() + std::ptrdiff_t(onset), x.end());
  r.whole = std::move(x);
  return r;
}

void extract_impact_modes(ImpactRecording& r) {
  ExtractOptions options;  // the defaults of `modalstudy extract`
  options.skip_contact_s = 0.5e-3;
  options.max_attack_skip_s = 20e-3;
  const ExtractedFeatures f = extract_features(r.whole, r.sample_rate_hz, options);
  if (f.modes.empty()) throw InputError(SourceLocation{r.path, 0, 0}, "no modes found above the noise floor");
  r.modes = f.modes;
  r.noise_sigma = f.noise_sigma;
}

}  // namespace ms::cli
