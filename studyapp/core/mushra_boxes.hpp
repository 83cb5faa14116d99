// The data of a MUSHRA box plot after BS.1534-3 post-screening, one recipe for every picture of MUSHRA
// results (the experimenter view, `modalstudy stats mushra --plot`): per condition, the ratings of the
// assessors post-screening keeps, and the mean with its CI over them (mushra_analyse's statistics).
#pragma once
#include <string>
#include <vector>

#include "analysis/stats/mushra.hpp"

namespace ms {

struct MushraBoxes {
  std::vector<std::string> conditions;       // in order of first appearance
  std::vector<std::vector<double>> ratings;  // of the kept assessors
  std::vector<double> means, ci_low, ci_high;  // NaN where undefined (no kept rating, n < 2)
  std::size_t assessors = 0, kept = 0;
};

MushraBoxes mushra_boxes(const std::vector<MushraRating>& ratings, const MushraOptions& options);

// The hidden reference of a studyapp MUSHRA block, read from its automatic anchors' names
// ("full~lp3500" -> "full"); "" when the conditions hold no automatic anchor.
std::string reference_from_anchor_names(const std::vector<std::string>& conditions);

}  // namespace ms
