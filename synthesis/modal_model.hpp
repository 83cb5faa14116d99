// ModalModel: the sound of a struck object as a sum of exponentially decaying sinusoids,
// y(t) = sum_n amp_n e^{-decay_n t} sin(2 pi freq_n t + phase_n)   (van den Doel & Pai; Ren et al.).
#pragma once
#include <string>
#include <vector>

namespace ms {

struct Mode {
  double freq_hz = 0.0;      // damped frequency
  double decay_per_s = 0.0;  // amplitude decay rate d (Sterling's c = 2d)
  double amp = 0.0;          // initial amplitude for an ideal unit impulse
  double phase_rad = 0.0;    // 0 for an object at rest struck at t = 0
};

struct ModalModel {
  std::vector<Mode> modes;
  // Optional per-hit-point gains: hit_gains[h][n] multiplies amp of mode n when struck at point h.
  std::vector<std::string> hit_point_names;
  std::vector<std::vector<double>> hit_gains;
};

// The model as heard when struck at hit point `index` (amp_n *= hit_gains[index][n]).
ModalModel at_hit_point(const ModalModel& model, std::size_t index);

// Drop modes at or above limit_hz (Nyquist), and any at or below 0 Hz, which cannot sound; returns how
// many were dropped.
std::size_t drop_modes_at_or_above(ModalModel& model, double limit_hz);

}  // namespace ms
