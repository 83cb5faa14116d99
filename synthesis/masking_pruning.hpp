// Masking-based mode pruning and progressive ordering (van den Doel, Pai et al. 2002,
// shared/papers/003): which modes of a modal model are inaudible, and in what order to add the rest.
//
// The rule, exactly (every quantity per mode n of the input, in input order):
//   power      P_n = amp_n^2 / decay_n                       (decay 0 is rejected: infinite power)
//   level      L_n = L_play + 10 log10(P_n / sum_k P_k)  dB  (-inf for amp 0; all -inf if all amps 0)
//   Bark       z_n = 13 atan(0.00076 f_n) + 3.5 atan((f_n/7500)^2)           (Zwicker-Terhardt)
//   masking of mode m by mode n (n != m, P_n > 0; a silent mode masks nothing):
//              M(n,m) = L_n - a_v - 25 (z_n - z_m)                     if z_m <= z_n
//                       L_n - a_v - max(0, 22 - L_n/5) (z_m - z_n)    if z_m >  z_n
//   masking    T_m = max_n M(n,m)                  (combine max: the upper envelope; the default)
//                    10 log10 sum_n 10^(M(n,m)/10) (combine sum: maskings add in power)
//              T_m = -inf when no other mode masks.
//   quiet      Q_m = Terhardt's threshold in quiet at f_m (synthesis/threshold_in_quiet.hpp)
//   audible    P_m > 0 and L_m >= max(T_m, Q_m)   (inaudible = strictly below either)
//   loudness   A_m = L_m - max(T_m, Q_m), dB above the masking threshold (finite, or -inf for amp 0)
// Orderings, descending, ties by input index: naive = amp, energy = P, loudness = A.
// Method masking keeps the audible modes ordered by `order`; methods naive, energy and loudness keep
// every mode (no masking: the progressive-synthesis baselines of the 2002 study) ordered by
// themselves. The paper's vase (179 modes, a_v = 5 dB at 70 dB playback: 45 survive, its Fig. 3)
// cannot be reproduced here: its mode data were not published.
#pragma once
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "synthesis/modal_model.hpp"
#include "synthesis/name_table.hpp"

namespace ms {

enum class PruneMethod { masking, naive, energy, loudness };
enum class ModeOrder { naive, energy, loudness };
enum class MaskingCombine { max, sum };
inline constexpr NameTable<PruneMethod, 4> kPruneMethodNames{{{PruneMethod::masking, "masking"},
                                                              {PruneMethod::naive, "naive"},
                                                              {PruneMethod::energy, "energy"},
                                                              {PruneMethod::loudness, "loudness"}}};
inline constexpr NameTable<ModeOrder, 3> kModeOrderNames{
    {{ModeOrder::naive, "naive"}, {ModeOrder::energy, "energy"}, {ModeOrder::loudness, "loudness"}}};
inline constexpr NameTable<MaskingCombine, 2> kMaskingCombineNames{
    {{MaskingCombine::max, "max"}, {MaskingCombine::sum, "sum"}}};

std::optional<PruneMethod> parse_prune_method(std::string_view name);
std::optional<ModeOrder> parse_mode_order(std::string_view name);
std::optional<MaskingCombine> parse_masking_combine(std::string_view name);
std::string_view to_string(PruneMethod method);
std::string_view to_string(ModeOrder order);
std::string_view to_string(MaskingCombine combine);

// Field names are those a protocol writes: prune: {method: masking, threshold_db: 16, order: energy}.
struct PruneOptions {
  PruneMethod method = PruneMethod::masking;
  double threshold_db = 16.0;  // a_v; the 2002 study's median optimum (subjects ranged 3-20 dB)
  // L_play [dB SPL]: the level the whole model is played at, shared among the modes by their
  // time-integrated powers A^2/D (the paper's maskers; its "reference playback level ... (level
  // immediately after impact)" calibrates this total, it does not make the shares onset powers A^2).
  double playback_db = 70.0;
  MaskingCombine combine = MaskingCombine::max;
  ModeOrder order = ModeOrder::energy;  // used by method masking only
};

inline constexpr double kThresholdDbMin = -20.0, kThresholdDbMax = 60.0;
inline constexpr double kPlaybackDbMin = 0.0, kPlaybackDbMax = 130.0;

// A bad option or a bad mode. field() is the protocol field ("threshold_db", "playback_db") or the
// mode column ("freq_hz", "decay_per_s", "amp"); mode() is the mode's index, or kNoMode for options.
// The caller adds the location it knows (a CSV line, a YAML node, a command-line option).
class PruneError : public std::invalid_argument {
 public:
  static constexpr std::size_t kNoMode = std::numeric_limits<std::size_t>::max();
  PruneError(std::string field, std::size_t mode, std::string problem);
  const std::string& field() const { return field_; }
  std::size_t mode() const { return mode_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string field_;
  std::size_t mode_;
  std::string problem_;
};

// The ordering a method uses: `order` for masking, the method's own criterion otherwise.
ModeOrder effective_order(const PruneOptions& options);

// Throws PruneError when threshold_db or playback_db is not finite or outside its range above.
void validate_prune_options(const PruneOptions& options);

// P_n = amp^2/decay. Throws PruneError for freq <= 0, decay <= 0, amp < 0, anything not finite, or
// a power that overflows.
std::vector<double> mode_powers(const ModalModel& model);

// L_n = playback_db + 10 log10(P_n / sum P), computed relative to the largest power so that the sum
// cannot overflow. -inf where P_n = 0 (or P_n / P_max underflows: more than ~3200 dB down).
std::vector<double> mode_levels_db(const std::vector<double>& power, double playback_db);

// T_m for every mode from its Bark position z and level L (equal lengths; -inf levels mask nothing).
// Both sweep the modes in ascending Bark. The fast one is O(N log N) for max (upper side: the
// envelope of the maskers' lines in a Li Chao tree over the sorted Bark positions; lower side: a
// suffix maximum of L_n - 25 z_n) and O(N (log N + 27 B)) for sum (lower side factorised through the
// common 25 dB/Bark slope; upper side: maskers bucketed by slope into B buckets of 1.09 dB/Bark, each
// held as Taylor moments about the bucket's centre; B = 19 for the benchmark's random modes).
// Agreement with masking_threshold_db_naive, the O(N^2) definition (tests/analysis):
//   max: the same masker is chosen and its value recomputed by the naive formula, so equal up to
//        rounding among near-tied maskers (tested to 1e-9 dB, or 1e-11 |T| where |T| > 100 dB);
//   sum: Taylor truncation and rounding stay below ~1e-11 of T in power (RateBuckets in the .cpp),
//        i.e. ~5e-11 dB (tested to the same 1e-9 dB; measured 4e-14 dB).
std::vector<double> masking_threshold_db(const std::vector<double>& bark,
                                         const std::vector<double>& level_db, double threshold_db,
                                         MaskingCombine combine);
std::vector<double> masking_threshold_db_naive(const std::vector<double>& bark,
                                               const std::vector<double>& level_db,
                                               double threshold_db, MaskingCombine combine);

// `indices` sorted by the criterion's key, descending, ties by index ascending.
std::vector<std::size_t> order_modes(std::vector<std::size_t> indices, ModeOrder order,
                                     const ModalModel& model, const std::vector<double>& power,
                                     const std::vector<double>& loudness_db);

struct PruneResult {
  std::vector<double> power;         // P_n
  std::vector<double> level_db;      // L_n (-inf for amp 0)
  std::vector<double> bark;          // z_n (Zwicker-Terhardt)
  std::vector<double> masking_db;    // T_n, from all other modes (-inf when none masks)
  std::vector<double> quiet_db;      // Q_n
  std::vector<double> loudness_db;   // A_n = L_n - max(T_n, Q_n)
  std::vector<bool> audible;         // the masking rule's verdict, whatever the method
  std::vector<std::size_t> kept;     // mode indices in progressive order
  std::vector<std::size_t> dropped;  // mode indices not kept, ascending
};

// Validates the options and the modes (PruneError), then applies the rule above.
PruneResult prune_modes(const ModalModel& model, const PruneOptions& options);

// The progressive model of the first min(k, kept.size()) kept modes, in kept order (hit-point gains,
// if any, are carried along for those modes).
ModalModel progressive_model(const ModalModel& model, const PruneResult& result, std::size_t k);

}  // namespace ms
