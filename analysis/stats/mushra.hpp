// MUSHRA results (ITU-R BS.1534-3): post-screening of assessors, per-condition and per-item means
// with t-based 95 % confidence intervals.
//
// Post-screening (BS.1534-3 §4.1.2): an assessor is excluded when they rate the hidden reference
// below 90 in more than 15 % of the items they rated it. The same recommendation flags an assessor
// who rates the mid-range anchor above 90 in more than 15 % of the items; that check is always
// reported and excludes only when `screen_anchors` is set.
// Statistics (BS.1534-3 §9.2): for each condition over the N ratings of the included assessors,
//   mean = (1/N) sum u_i, s = sqrt(sum (u_i - mean)^2 / (N - 1)),
//   CI = mean +- t_{N-1, (1+level)/2} s / sqrt(N);
// the interval is reported as computed even where it passes the 0..100 scale (clipping it would
// change its coverage and hide how wide it is); such intervals are marked (ci_past_scale).
// per item the same over the included assessors. Repeated ratings of one assessor, item and
// condition are first averaged (one rating per assessor, item and condition).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

struct MushraRating {
  std::string subject, item, condition;
  double rating = 0;  // 0..100
};

struct MushraOptions {
  std::string reference = "reference";
  std::vector<std::string> anchors;  // conditions checked against the anchor rule (each alone)
  double reference_min = 90.0;       // a hidden reference below this counts as a miss
  double anchor_max = 90.0;          // an anchor above this counts as a miss
  double max_fraction = 0.15;        // tolerated fraction of missed items
  bool screen_anchors = false;       // also exclude assessors failing the anchor check
  double conf_level = 0.95;
};

struct MushraAnchorCheck {
  std::string anchor;
  std::size_t items = 0, above = 0;  // items where the assessor rated this anchor; rated above anchor_max
  bool fails = false;
};

struct MushraAssessor {
  std::string subject;
  std::size_t reference_items = 0, reference_below = 0;  // items with a reference rating; misses
  std::vector<MushraAnchorCheck> anchors;                // one per MushraOptions::anchors
  bool reference_fails = false, anchor_fails = false;    // anchor_fails: any anchor fails
  bool excluded = false;
};

struct MushraStat {
  std::string condition;
  std::size_t n = 0;
  double mean = 0, sd = 0;
  std::optional<double> ci_low, ci_high;  // need n >= 2; as computed, never clipped to the scale
  bool ci_past_scale = false;             // the interval reaches below 0 or above 100 (printed marked)
};

struct MushraItem {
  std::string item;
  std::vector<MushraStat> conditions;
};

struct MushraResult {
  std::vector<MushraAssessor> assessors;  // in order of first appearance
  std::size_t included = 0;
  std::size_t averaged = 0;               // assessor/item/condition cells with repeated ratings
  std::vector<MushraStat> conditions;     // in order of first appearance
  std::vector<MushraItem> items;
};

MushraResult mushra_analyse(const std::vector<MushraRating>& ratings, const MushraOptions& options);

// The ratings of a tidy table, one row per rating. A column left empty is the first of its defaults
// the table has (webMUSHRA's names accepted): subject participant|subject|session_uuid, item
// trial|item|trial_id, condition condition|rating_stimulus, rating rating|rating_score.
// InputError at the cell for a rating outside 0-100 or an empty name, and at the header when the
// hidden reference or a named anchor is not a condition. Anchors left empty in `options` become the
// conditions named anchor*.
struct MushraColumns {
  std::string subject, item, condition, rating;
};
struct MushraTable {
  std::vector<MushraRating> ratings;
  MushraOptions options;  // `options` with the anchors resolved
};
MushraTable mushra_from_table(const TidyCsv& table, const MushraColumns& columns, const MushraOptions& options);

// Mean, sd and t-based interval of a sample.
MushraStat describe(const std::string& name, const std::vector<double>& values, double conf_level);

}  // namespace ms
