// Threshold of an adaptive staircase track (Levitt 1971), the one definition used by the live track
// (studyapp/core/staircase_track), the export's staircase.csv and `modalstudy stats staircase`.
// A reversal is a trial after which the level moves in the direction opposite to its previous move
// (trials after which it does not move change nothing); its level is the level presented at that
// trial. The threshold is the mean level of the reversals after the first two (of all of them when
// there are at most four), or of the last k when k is given; with log_scale the mean is geometric.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

struct StaircaseOptions {
  std::optional<std::size_t> last_k;  // average the last k reversals instead of all but the first two
  bool log_scale = false;             // geometric mean (levels on a ratio scale, all > 0)
};

struct StaircaseThreshold {
  std::vector<std::size_t> reversal_trials;  // 0-based trial index of every reversal
  std::vector<double> reversal_levels;
  std::size_t used = 0;                      // reversals averaged
  std::optional<double> threshold;           // none without reversals
  std::optional<double> sd;                  // of the used reversal levels (log units with log_scale), used >= 2
};

// `levels` are the levels presented, in order; `next_level` is where the track moved after the last
// answer (without it a reversal at the last trial cannot be seen, and is not counted).
StaircaseThreshold staircase_threshold(const std::vector<double>& levels, std::optional<double> next_level,
                                       const StaircaseOptions& options = {});

// Reversals skipped by default: the approach to the threshold, not the threshold.
std::size_t staircase_default_skip(std::size_t reversals);

// The tracks of a tidy table, one row per trial: grouped by the `track` columns (in order of first
// appearance), ordered by `trial` when given (stable, else file order), with the level after the last
// answer from `next_level` when the table has that column. InputError at the cell for a level that is
// not a number, or not above 0 with log_scale; "no data rows".
struct StaircaseColumns {
  std::string level, trial, next_level;  // trial, next_level: optional
  std::vector<std::string> track;
};
struct StaircaseTrackLevels {
  std::string name;  // the track columns' values joined by '/', "" without track columns
  std::vector<double> levels;
  std::optional<double> next_level;
};
struct StaircaseTracks {
  bool has_next_level = false;
  std::vector<StaircaseTrackLevels> tracks;
};
StaircaseTracks staircase_tracks_from_table(const TidyCsv& table, const StaircaseColumns& columns, bool log_scale);

}  // namespace ms
