// Method-of-adjustment answers analysed as Sterling et al. (2019, section 1.3.2) report their hand-tuning
// study: per object (within a group, e.g. the study's section), the time each answer took and the sounds
// played for it, as box summaries (Fig. 1.11), and per tuned parameter the values chosen across the
// listeners (the spread of Fig. 1.10) and, where the target's true value is known, each choice's error
// as the log ratio log10(chosen / true) (0: exact; 0.301: twice the truth; -0.301: half).
//
// The table is the export's adjust.csv: one row per slider of an answer, the answer's plays and rt_ms
// repeated on each of its rows (counted once per answer), and `truth` (the target's value of the row's
// key, NA where unknown) when the protocol's targets state it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "analysis/stats/box_summary.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {

struct AdjustColumns {
  std::string object = "stimulus";  // what was tuned
  std::string group;                // "" = one group (e.g. "section")
  std::vector<std::string> answer = {"participant", "session", "block", "trial"};  // the rows of one answer
  std::string key = "key", value = "value", plays = "plays", rt_ms = "rt_ms";
  std::string truth;                // "" = no true values
};

struct AdjustParameter {
  std::string key;
  BoxSummary chosen;                 // the values chosen, one per answer
  double mean = 0, sd = 0;           // sd is NaN for a single answer
  std::optional<double> truth;       // the target's value, where the table states it
  std::optional<BoxSummary> log10_ratio;  // log10(chosen / truth) over the positive choices
  double log10_ratio_mean = 0, log10_ratio_rms = 0;
  std::size_t not_positive = 0;      // choices <= 0: no log ratio
};

struct AdjustObject {
  std::string group, object;
  BoxSummary time_s, plays;          // one value per answer
  std::vector<AdjustParameter> parameters;  // in order of first appearance
};

struct AdjustGroup {
  std::string group;
  BoxSummary time_s, plays;          // every answer of the group, all objects pooled (Fig. 1.11)
};

struct AdjustSummary {
  std::vector<AdjustObject> objects;  // groups, then objects, in order of first appearance
  std::vector<AdjustGroup> groups;
};

// InputError at FILE:LINE:COLUMN for a missing column, no rows, a value, plays or rt_ms that is not a
// finite number (plays and rt_ms also not negative), rows of one answer that disagree on plays or
// rt_ms, a key given twice in one answer, a truth that is neither a number nor NA/empty, or two truths
// for one object's key.
AdjustSummary adjust_summary(const TidyCsv& table, const AdjustColumns& columns);

}  // namespace ms
