// The residual of a material estimate; see residual.hpp.
#include "analysis/estimation/residual.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "synthesis/residual_transfer.hpp"

namespace ms {

ResidualSpectrogram residual_spectrogram(const std::vector<float>& recording, const std::vector<float>& synthesis,
                                         double sample_rate_hz, const std::vector<Mode>& source_modes,
                                         const ResidualOptions& options) {
  if (recording.empty()) throw std::invalid_argument("residual: the recording is empty");
  const std::size_t samples =
      std::min(recording.size(), std::max<std::size_t>(1, std::size_t(std::llround(options.max_duration_s * sample_rate_hz))));
  std::vector<float> heard(recording.begin(), recording.begin() + std::ptrdiff_t(samples));
  std::vector<float> made(samples, 0.0f);
  std::copy_n(synthesis.begin(), std::min(samples, synthesis.size()), made.begin());

  Stft stft(options.grid);
  const std::vector<double> recorded = stft.power(heard), modal = stft.power(made);
  ResidualSpectrogram out;
  out.sample_rate_hz = sample_rate_hz;
  out.grid = options.grid;
  out.frames = options.grid.frames_for(samples);
  out.power.resize(recorded.size());
  for (std::size_t i = 0; i < recorded.size(); ++i) out.power[i] = float(std::max(0.0, recorded[i] - modal[i]));
  for (const Mode& m : source_modes)
    if (m.freq_hz > 0.0 && m.freq_hz < 0.5 * sample_rate_hz) out.modes.push_back(m);
  if (out.modes.empty()) throw std::invalid_argument("residual: no source mode below Nyquist to guide its transfer");
  return out;
}

ResidualSpectrogram estimate_residual(const std::vector<float>& recording, double sample_rate_hz,
                                      const ObjectEigen& object, const Excitation& excitation,
                                      const Candidate& material, const ResidualOptions& options) {
  const ModalModel model = candidate_model(object, material, 0.5 * sample_rate_hz);
  const std::size_t samples =
      std::min(recording.size(), std::size_t(std::llround(options.max_duration_s * sample_rate_hz)));
  const std::vector<float> synthesis = render_candidate(model, excitation, sample_rate_hz, samples);
  return residual_spectrogram(recording, synthesis, sample_rate_hz, heard_modes(model.modes, excitation), options);
}

std::string residual_path_for(const std::string& material_path) {
  std::filesystem::path p(material_path);
  p.replace_extension(".residual.msr");
  return p.string();
}

std::string write_residual(const std::string& material_path, const std::vector<float>& recording,
                           double sample_rate_hz, const ObjectEigen& object, const Excitation& excitation,
                           const Candidate& material, const std::string& source, const ResidualOptions& options) {
  ResidualSpectrogram residual = estimate_residual(recording, sample_rate_hz, object, excitation, material, options);
  residual.source = source;
  const std::string path = residual_path_for(material_path);
  write_residual_file(path, residual);
  return path;
}

}  // namespace ms
