// A signal from a power spectrogram alone: Griffin & Lim's (1984) iterative STFT magnitude
// reconstruction with the momentum of the fast variant (Perraudin, Balazs & Sondergaard 2013,
// c_n = t_n + alpha (t_n - t_{n-1})), on the residual's grid (residual_stft.hpp). The initial phases
// are uniform from a seeded generator, so one seed always gives the same samples. Spectral
// convergence, 20 log10 (|| |STFT x| - S ||_F / || S ||_F) with S the target magnitude, says how near
// the result's spectrogram is to the target.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "synthesis/residual_stft.hpp"

namespace ms {

struct GriffinLimOptions {
  std::size_t iterations = 100;
  double momentum = 0.99;  // alpha; 0 is the original algorithm
  std::uint64_t seed = 1;  // initial phases
};

struct GriffinLimResult {
  std::vector<float> samples;
  double spectral_convergence_db = 0.0;  // of the returned samples; -infinity for a silent target
};

// `power`: grid.frames_for(samples) x grid.bins(), frame-major, every value >= 0. Throws
// std::invalid_argument when the sizes disagree. Allocates once before the iterations, not in them.
GriffinLimResult griffin_lim(const std::vector<float>& power, const StftGrid& grid, std::size_t samples,
                             const GriffinLimOptions& options = {});

// 20 log10 (|| |STFT x| - sqrt(power) ||_F / || sqrt(power) ||_F) over x's frames.
double spectral_convergence_db(const std::vector<float>& x, const std::vector<float>& power, const StftGrid& grid);

}  // namespace ms
