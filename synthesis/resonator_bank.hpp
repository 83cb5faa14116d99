// ResonatorBank: real-time rendering of a modal model, one complex one-pole resonator per mode,
//   z[n+1] = r e^{i theta} z[n],  y[n] = sum_modes Im z[n],   r = e^{-d/fs}, theta = 2 pi f/fs,
// in float, 8 modes per SIMD vector, no allocation after construction. Every kBlockFrames samples
// the float state is re-anchored to a double-precision state advanced by the exact pole power, so
// rounding never accumulates and long high-Q modes stay on the closed form. A finite contact is
// integrated exactly (in double) during the contact; the free decay after it runs in the bank.
#pragma once
#include <cstddef>
#include <vector>

#include "synthesis/excitation.hpp"
#include "synthesis/modal_model.hpp"

namespace ms {

class ResonatorBank {
 public:
  static constexpr std::size_t kBlockFrames = 512;

  // Modes at or above Nyquist must have been removed by the caller (see render_stimulus).
  ResonatorBank(const ModalModel& model, const Excitation& excitation, double sample_rate_hz);

  // Writes the next `frames` samples (overwrites out). Allocation-free.
  void render(float* out, std::size_t frames);

  std::size_t mode_count() const { return mode_count_; }

 private:
  void start_block();
  void run_block(float* out, std::size_t count);

  std::size_t mode_count_ = 0;
  std::size_t padded_ = 0;  // multiple of the SIMD width
  // Double-precision anchor: state at the start of the current block, pole^kBlockFrames.
  std::vector<double> anchor_re_, anchor_im_, step_re_, step_im_;
  // Float running state and one-sample pole, SoA.
  std::vector<float> re_, im_, c_, s_;
  std::vector<float> lanes_;  // per-sample partial sums, kBlockFrames x 8
  std::vector<double> head_;  // exact output during the contact phase
  std::size_t position_ = 0;       // samples emitted so far
  std::size_t block_offset_ = 0;   // position inside the current block
};

// Convenience: the whole signal (allocates the output).
std::vector<float> render_bank(const ModalModel& model, const Excitation& excitation,
                               double sample_rate_hz, std::size_t frames);

}  // namespace ms
