// Residual file (MATERIAL.residual.msr): what linear modal synthesis could not make of a recording,
// as a power spectrogram on a stated STFT (residual_stft.hpp), with the modes of the source object
// that guide its transfer to other objects (residual_transfer.hpp). Written by `modalstudy estimate
// -o MATERIAL.yaml` beside the material; read by parameter sets (`residual: {file: X}`).
//
// The format: a YAML header, a line "...", then the payload.
//   format: modalstudy-residual 1
//   source: "modalstudy estimate spoon.wav"        # optional provenance, one line
//   sample_rate_hz: 44100
//   stft: {window: hann, fft_size: 1024, hop: 256}  # periodic Hann, frames centred on m * hop
//   bins: 513                                       # fft_size / 2 + 1
//   frames: 345
//   power: float32-le                               # |X_m[k]|^2, full-scale units, FFTW unnormalised
//   modes: {freq_hz: [...], decay_per_s: [...], amp: [...], phase_rad: [...]}   # as heard, >= 1
//   ...
//   <frames x bins little-endian float32, frame-major: frame 0's bins 0..bins-1, then frame 1, ...>
// The header's numbers are written in their shortest exact form, the payload bit for bit, so writing
// and reading give back the same spectrogram.
#pragma once
#include <string>
#include <vector>

#include "synthesis/bounded_file.hpp"
#include "synthesis/modal_model.hpp"
#include "synthesis/residual_stft.hpp"

namespace ms {

inline constexpr FileLimit kResidualFileLimit{"residual file", 512 * kMiB};

struct ResidualSpectrogram {
  std::string source;           // provenance ("" when none)
  double sample_rate_hz = 44100;
  StftGrid grid;
  std::size_t frames = 0;
  std::vector<Mode> modes;      // the source object's modes as heard (excitation applied), >= 1
  std::vector<float> power;     // frames x grid.bins(), frame-major, every value finite and >= 0

  float at(std::size_t frame, std::size_t bin) const { return power[frame * grid.bins() + bin]; }
};

// Reads and checks a residual file (at most kResidualFileLimit bytes). Every problem is one InputError
// naming the file: with line and column in the header, with the frame and bin in the payload.
ResidualSpectrogram read_residual_file(const std::string& path);
ResidualSpectrogram parse_residual_file(const std::string& bytes, const std::string& file_for_errors);

// The file's bytes for `r` (parse_residual_file of them gives back `r`). Throws std::invalid_argument
// when `r` is not a valid residual (sizes, values, no modes).
std::string residual_file_bytes(const ResidualSpectrogram& r);

// Checks and writes `r` to `path` through a temporary, so a failure leaves no partial file.
void write_residual_file(const std::string& path, const ResidualSpectrogram& r);

}  // namespace ms
