// The residual of one recorded object heard on another (patent US 9,401,684 Sec. 6.2, Algorithm 1):
// the i-th source mode and the i-th target mode, both in ascending frequency, form a pair (modes move
// with the geometry and keep their order for objects of one kind). Per pair the source residual is
//   (1) shifted in frequency by f_t - f_s,
//   (2) stretched in time by the decay ratio d_s / d_t (target time t reads source time t d_t / d_s),
//   (3) scaled pixel by pixel by A = P_t / P_s'', the target mode's power over the source mode's after
//       the same shift and stretch (both in closed form, residual_stft.hpp: the shifted source mode is
//       the same sinusoid at f_t, so no window scalloping enters A), so that the residual keeps its
//       relation to the mode it sat beside,
// and the result is kept in the target mode's neighbourhood, between the midpoints to its paired
// neighbours (the lowest reaching 0 Hz, the highest Nyquist); the neighbourhoods stitched are the
// target's residual, turned into samples by Griffin-Lim (griffin_lim.hpp).
// The residual is interpolated bilinearly in power between frames and bins; on the source object itself every
// shift is 0 and every ratio 1, so the transfer returns the source spectrogram bit for bit.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "synthesis/excitation.hpp"
#include "synthesis/griffin_lim.hpp"
#include "synthesis/modal_model.hpp"
#include "synthesis/residual_file.hpp"

namespace ms {

// The modes as the listener hears them after the strike: amp and phase of g a e^{i phase} G e^{p tau},
// the free decay's state when a contact of tau ends (g the strike gain, G the contact's factor,
// p = -d + i 2 pi f; tau = 0 and G = 1 for the impulse), as the renderers apply them, with its time
// origin moved to the contact's end. (Extrapolated back to t = 0, a mode that dies within the contact
// would count e^{d tau} times louder than it sounds.)
std::vector<Mode> heard_modes(const std::vector<Mode>& modes, const Excitation& excitation);

// Pixel scales are taken against a floor this far below each mode's peak in the frame (-30 dB), so
// that A is the pixel ratio where the mode is present (its main lobe) and tends to the ratio of the
// two modes' peaks in that frame elsewhere, instead of a ratio of window sidelobes or of 0/0.
inline constexpr double kPixelScaleFloor = 1e-3;
// No mode pair makes its neighbourhood louder than this (+60 dB): the pair of a loud target mode and
// a source mode the strike hardly excited would otherwise amplify the residual without bound. A
// source mode 120 dB under the loudest source mode leaves its neighbourhood unscaled.
inline constexpr double kMaxPixelScale = 1e6;

// The target's residual power: target_frames x source.grid.bins(), frame-major. `target`: the heard
// modes of the object (below the source's Nyquist; others are ignored). Without a pair (no target
// mode) the source spectrogram is returned, cut or padded with silence to target_frames.
std::vector<float> transfer_residual_power(const ResidualSpectrogram& source, const std::vector<Mode>& target,
                                           std::size_t target_frames);

// The target's residual as `samples` samples at source.sample_rate_hz: the transferred power through
// Griffin-Lim. Throws std::invalid_argument when sample_rate_hz differs from the residual's.
GriffinLimResult render_transferred_residual(const ResidualSpectrogram& source, const std::vector<Mode>& target,
                                             double sample_rate_hz, std::size_t samples,
                                             const GriffinLimOptions& options = {});

// What a parameter set's `residual:` adds: render_transferred_residual of `samples.size()` samples
// with `seed` (the default iterations), times 10^(gain_db / 20), added to `samples`.
void add_transferred_residual(std::vector<float>& samples, const ResidualSpectrogram& source,
                              const std::vector<Mode>& target, double sample_rate_hz, double gain_db,
                              std::uint64_t seed);

}  // namespace ms
