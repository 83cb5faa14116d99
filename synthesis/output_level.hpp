// Output level: none (the model's own scale), peak (max |y| = target), or equalised over the first
// 5 ms (RMS of the attack = target), as in van den Doel et al.'s stimuli. Targets in dBFS.
#pragma once
#include <string>
#include <vector>

#include "synthesis/name_table.hpp"

namespace ms {

enum class LevelMode { none, peak, attack_rms };
inline constexpr NameTable<LevelMode, 3> kLevelModeNames{
    {{LevelMode::none, "none"}, {LevelMode::peak, "peak"}, {LevelMode::attack_rms, "attack_rms"}}};

struct OutputLevel {
  LevelMode mode = LevelMode::none;
  double target_dbfs = -1.0;     // peak: -1 dBFS; attack RMS: e.g. -20 dBFS
  double attack_window_s = 0.005;
};

LevelMode parse_level_mode(const std::string& name);  // "none" | "peak" | "attack_rms"
std::string to_string(LevelMode mode);

// The gain that brings `samples` to the level; 1 for none, or for silence.
double level_gain(const std::vector<float>& samples, double sample_rate_hz, const OutputLevel& level);

}  // namespace ms
