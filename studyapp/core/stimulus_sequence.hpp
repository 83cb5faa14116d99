// A sequence stimulus: several strikes in one sound, each another stimulus of the protocol placed at
// its onset with its gain, e.g. an object that falls and bounces, struck at a different area each time
// (Skandalou & Ireland 2017, Exp. 2). A protocol writes
//   bounce: {sequence: [rim, middle, rim], onsets_s: [0, 0.42, 0.71], gains_db: [0, -3, -6]}
// The parts are rendered (or read) as they would be alone, so each keeps its own level; the sequence
// adds them, part i times 10^(gain_db_i / 20) from frame round(onset_s_i * rate) on. The sum is not
// levelled again: a strike's gain is relative to that part as the protocol plays it alone.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "synthesis/input_error.hpp"

namespace ms {

inline constexpr double kSequenceMaxS = 600.0;  // onsets and the whole sound, as a parameter set's duration_s
inline constexpr double kSequenceGainDbMin = -120.0, kSequenceGainDbMax = 40.0;

// One part as the mixer sees it: its samples, where it starts and how loud.
struct SequenceStrike {
  const std::vector<float>* samples = nullptr;
  double onset_s = 0.0, gain_db = 0.0;
};

// The frame at which a part starts.
std::size_t onset_frame(double onset_s, double sample_rate_hz);

// The sum of the parts at their onsets. Throws InputError at `where` when the sound would last more
// than kSequenceMaxS (a sequence of sequences can reach that even when every onset is in range).
std::vector<float> mix_sequence(const std::vector<SequenceStrike>& strikes, double sample_rate_hz,
                                const SourceLocation& where, const std::string& name);

// One part as the recipe hash sees it: the part's own hash, its onset and its gain.
struct SequenceRecipePart {
  std::string hash;
  double onset_s = 0.0, gain_db = 0.0;
};

// SHA-256 over the rate and every part's hash, onset and gain (in order), so a sequence's hash
// changes whenever any part's sound, placement or level does.
std::string sequence_hash(const std::vector<SequenceRecipePart>& parts, double sample_rate_hz);

}  // namespace ms
