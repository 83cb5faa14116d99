// Protocol model: a listening study as read from protocols/*.yaml (DESIGN.md §4) — named stimuli
// (parameter set + overrides, derived anchor, recording, sequence of other stimuli) and an ordered list of typed blocks.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "synthesis/input_error.hpp"

namespace ms {

// A stimulus name as written in a block, with where it was written (for "did you mean").
struct StimulusRef {
  std::string name;
  SourceLocation where;
};
using StimulusPair = std::array<StimulusRef, 2>;

enum class StimulusKind { paramset, derived, file, sequence };

// One strike of a sequence stimulus: another stimulus of the protocol, from its onset on, at its gain.
struct SequencePart {
  StimulusRef stimulus;
  double onset_s = 0.0, gain_db = 0.0;
};

struct StimulusSource {
  std::string name;
  StimulusKind kind = StimulusKind::paramset;
  SourceLocation where;               // the name key
  std::string path;                   // paramset or file path as written (relative to the protocol)
  SourceLocation path_where;
  std::vector<std::string> overrides; // "key=value" from `set:` and `prune:` (prune.key=value)
  std::vector<SourceLocation> override_where;  // where each of `overrides` was written
  StimulusRef derive_from;            // kind == derived
  double lowpass_hz = 0.0;
  std::vector<SequencePart> sequence; // kind == sequence: the strikes, onsets rising (stimulus_sequence.hpp)
  bool implicit = false;              // created by `anchors: auto`, not written by the author
  // What an identification answer should be: attribute -> label ({shape: disc, material: metal}), or
  // one label under the key "" (`truth: metal`). Exported as the `truth` column.
  std::vector<std::pair<std::string, std::string>> truth;
  // Design factors of the stimulus ({dataset: emg, shape: disc}), exported one column per factor.
  std::vector<std::pair<std::string, std::string>> factors;
};

enum class BlockType { instructions, ab, mushra, magnitude, identify, rating, adjust, staircase,
                       questionnaire, bs1116, limits, tokens, changepoint, unknown };
const std::vector<std::string>& block_type_names();  // in enum order, without "unknown"
std::string to_string(BlockType t);

enum class AbMode { same_different, preference, abx, two_afc, bipolar };
std::string to_string(AbMode m);

struct InstructionsBlock { std::string text; };
// A pair written as a triple [A, B, REF] (not in ABX) also plays REF after A and B: e.g. the recording
// against which two synthesis methods are compared on the bipolar -3..+3 scale.
struct AbBlock {
  AbMode mode = AbMode::same_different;
  std::vector<StimulusPair> pairs;
  std::vector<StimulusRef> references;  // empty, or one per pair
};
struct MushraBlock {
  std::optional<StimulusRef> reference;
  std::vector<StimulusRef> conditions;
  bool auto_anchors = false;
  std::vector<StimulusRef> anchors;  // with auto: the implicit derived stimuli (3.5 and 7 kHz)
};
struct MagnitudeBlock {
  std::optional<StimulusPair> modulus;
  double modulus_value = 100;        // the number the modulus pair stands for (exported; `stats magnitude` reads it)
  bool all_pairs = false;            // every unordered pair of `stimuli`
  bool identical_pairs = false;      // with all_pairs: also each stimulus against itself (2002 study)
  std::vector<StimulusPair> pairs;
  std::vector<StimulusRef> stimuli;
  // A bounded scale (the 2002 study's 1-10, 1 = identical): answers lie within [min, max]; without it
  // the ratio scale is open above. modulus_value defaults to max.
  struct Scale { double min = 1.0, max = 10.0; };
  std::optional<Scale> scale;
};
struct IdentifyBlock {
  std::vector<StimulusRef> stimuli;
  std::vector<std::string> labels;
};
struct RatingAttribute {
  std::string name;
  int points = 7;
  std::string low, high;
};
struct RatingBlock {
  std::vector<StimulusRef> stimuli;
  std::vector<RatingAttribute> attributes;
};
struct Slider {
  std::string key;  // dotted parameter-set key, e.g. damping.alpha1
  double min = 0.0, max = 1.0;
  SourceLocation where;
  std::string label = {}, low = {}, high = {};  // what the participant reads: its name and end labels
  bool show_value = false;       // show the parameter's value beside the slider
};
// `paramset` names a stimulus whose source is a parameter set; sliders override its keys live.
struct AdjustBlock {
  StimulusRef paramset;
  std::vector<Slider> sliders;
  std::optional<StimulusRef> target;  // a stimulus to match, playable beside the adjusted sound
};
// Transformed up-down staircase (Levitt 1971). Default 2-down-1-up: converges on 70.7 % correct.
// Each step plays the reference, then A and B in random order: one is the reference, the other the
// stimulus with `parameter` at the track's level; the listener says which of A/B is the reference.
struct StaircaseBlock {
  StimulusRef stimulus;
  std::optional<StimulusRef> reference;  // default: `stimulus` as defined (without the level)
  std::string parameter;    // dotted parameter-set key, e.g. prune.threshold_db
  SourceLocation parameter_where;
  double start = 0.0, step = -1.0;
  int down = 2, up = 1;
  int reversals = 8;
};
// Descending method of limits (van den Doel et al. 2002, Exp. 1): each series starts at `start` and
// lowers `parameter` by |step| per trial; every trial plays the reference, then the stimulus at the
// series' level, and the listener answers "same" or "different". The series ends at the first
// "different" or after the trial at `floor`; `repeats` series per block.
struct LimitsBlock {
  StimulusRef stimulus;
  std::optional<StimulusRef> reference;  // default: `stimulus` as defined (without the level)
  std::string parameter;                 // dotted parameter-set key, e.g. prune.threshold_db
  SourceLocation parameter_where;
  double start = 0.0, step = -1.0;       // step < 0: the series descends
  std::optional<double> floor;
  SourceLocation floor_where;
};
// The adaptive token procedure of van den Doel et al. 2002, Exp. 2 (analysis/stats/token_series.hpp):
// the token of K modes is `stimulus` (a parameter set whose `prune:` orders its modes) with prune.keep
// = K, for K = from, from - 1, ..., to; each step plays the current reference token, then the next
// token, and asks whether they differ. One series per trial, `repeats` series per block.
struct TokensBlock {
  StimulusRef stimulus;
  int from = 0, to = 1;                  // from > to >= 1
  SourceLocation from_where, to_where;
};
inline constexpr const char* kTokenParameter = "prune.keep";
// A change-point judgement over fixed-order sweeps (Skandalou & Ireland 2017, Exp. 3): each sweep is
// one trial playing its sounds in the written order, the swept parameter rising or falling through
// `values` (one per sound, the same for every sweep); the listener marks the sounds at which the
// material changed (zero or more, never the first: nothing comes before it). Sweeps are trials: their
// order is randomised with the block's `randomize`, the order within a sweep never.
struct ChangepointBlock {
  std::string parameter;                 // the swept quantity's name, as exported (e.g. Q)
  std::vector<double> values;
  SourceLocation values_where;
  std::vector<std::vector<StimulusRef>> sweeps;
};
struct Question {
  std::string id, text;
  std::vector<std::string> options;  // empty: free text
};
struct QuestionnaireBlock { std::vector<Question> questions; };
// ITU-R BS.1116 double-blind triple-stimulus with hidden reference: per condition a trial of the open
// reference and two sounds A and B, one of them the reference itself (which, drawn per trial); both
// A and B are graded on the continuous five-grade impairment scale 1.0-5.0 (5.0 imperceptible).
struct Bs1116Block {
  StimulusRef reference;
  std::vector<StimulusRef> conditions;
};

using BlockBody = std::variant<std::monostate, InstructionsBlock, AbBlock, MushraBlock, MagnitudeBlock,
                               IdentifyBlock, RatingBlock, AdjustBlock, StaircaseBlock, QuestionnaireBlock,
                               Bs1116Block, LimitsBlock, TokensBlock, ChangepointBlock>;

struct Block {
  BlockType type = BlockType::unknown;
  std::string type_name;       // as written (kept for unknown types)
  SourceLocation where;        // the block map
  SourceLocation type_where;
  std::string id;              // written, or "<type>-<n>" (1-based position) when absent
  bool id_written = false;
  SourceLocation id_where;
  bool randomize = true;
  bool training = false;
  // Blocks next to each other with the same shuffle group run in an order drawn per participant.
  std::string shuffle;         // "" = in the written place
  SourceLocation shuffle_where;
  int break_after = 0;         // trials between breaks; 0 = none
  int repeats = 1;
  bool listen_all = true;      // every sound must be played (MUSHRA: every slider moved) before answering
  std::string prompt;          // the participant's task ("" = the view's wording for the block type)
  bool feedback = false;       // after each answer, say whether it was right (training blocks)
  BlockBody body;

  // Every stimulus the block names (for validation and scheduling).
  std::vector<StimulusRef> referenced() const;
};

enum class Counterbalance { none, latin_square };

struct Protocol {
  std::string file;            // as given (used in messages)
  std::string base_dir;        // folder the relative paths are resolved against
  std::string study, title;
  double sample_rate_hz = 44100;
  std::uint64_t seed = 0;
  Counterbalance counterbalance = Counterbalance::none;
  bool allow_outside = false;
  bool export_personal = false;         // may participant codes leave the database on export?
  std::vector<StimulusSource> stimuli;  // in file order, implicit anchors appended
  std::vector<Block> blocks;
  // Written but not parsed (each reported by the parser already), so the validator says nothing
  // more about them: the names under stimuli: and the count of entries under blocks:.
  std::vector<std::string> unparsed_stimuli;
  std::size_t unparsed_blocks = 0;

  const StimulusSource* find_stimulus(const std::string& name) const;
  const Block* find_block(const std::string& id) const;
};

// Name of the implicit low-pass anchor of `reference` at `hz` ("full~lp3500").
std::string anchor_name(const std::string& reference, double hz);

}  // namespace ms
