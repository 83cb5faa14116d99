// The residual of a material estimate (patent US 9,401,684 Sec. 6.1): what the estimated linear modal
// synthesis cannot make of the recording, as power spectrograms on the residual's STFT
// (synthesis/residual_stft.hpp): P_residual = max(0, P_recording - P_synthesis), pixel by pixel, both
// from the onset. The estimate's heard modes are kept with it, to guide its transfer to other objects
// (synthesis/residual_transfer.hpp); MATERIAL.residual.msr holds both (synthesis/residual_file.hpp).
#pragma once
#include <string>
#include <vector>

#include "analysis/estimation/candidate_render.hpp"
#include "synthesis/residual_file.hpp"

namespace ms {

struct ResidualOptions {
  StftGrid grid;
  double max_duration_s = 2.0;  // the residual covers at most this much of the recording
};

// The residual of `recording` against `synthesis` (the same sample rate, both from the onset; the
// shorter is padded with silence). source_modes: the heard modes the synthesis was made of.
// Throws std::invalid_argument when the recording is empty or a mode cannot be stored (see
// residual_file.hpp).
ResidualSpectrogram residual_spectrogram(const std::vector<float>& recording, const std::vector<float>& synthesis,
                                         double sample_rate_hz, const std::vector<Mode>& source_modes,
                                         const ResidualOptions& options = {});

// The residual of an estimated material: the candidate rendered on the object as the estimation
// heard it (its modes below Nyquist, struck by `excitation`) and subtracted from the recording.
ResidualSpectrogram estimate_residual(const std::vector<float>& recording, double sample_rate_hz,
                                      const ObjectEigen& object, const Excitation& excitation,
                                      const Candidate& material, const ResidualOptions& options = {});

// MATERIAL.yaml -> MATERIAL.residual.msr (the material's extension, if any, replaced).
std::string residual_path_for(const std::string& material_path);

// What `modalstudy estimate -o MATERIAL.yaml` adds: estimate_residual written to
// residual_path_for(material_path) through a temporary (no partial file on any failure). `source`
// is the provenance line stored in it. Returns the path written.
std::string write_residual(const std::string& material_path, const std::vector<float>& recording,
                           double sample_rate_hz, const ObjectEigen& object, const Excitation& excitation,
                           const Candidate& material, const std::string& source,
                           const ResidualOptions& options = {});

}  // namespace ms
