// BS.1116 results (ITU-R BS.1116-3, double-blind triple-stimulus with hidden reference). The difference
// grade of a trial is the condition's grade minus the hidden reference's (−4..4; negative when the
// condition was heard as impaired). Per condition: each assessor's difference grades averaged (repeats),
// then over the assessors the mean, sample sd and t-based interval, as for MUSHRA
//   mean ± t_{N−1, (1+level)/2} s / √N.
// Per assessor, for post-screening by the experimenter (nothing is excluded here): the trials where the
// hidden reference was graded below the condition (a positive difference grade: the reference not
// identified), and a one-sided one-sample t-test of all their difference grades against 0 (H1: mean < 0,
// they hear the conditions as impaired); an assessor whose p is large cannot tell the reference.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "analysis/stats/mushra.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {

struct Bs1116Grade {
  std::string subject, condition;
  double diffgrade = 0;  // condition grade − hidden reference grade
};

struct Bs1116Assessor {
  std::string subject;
  std::size_t trials = 0, positive = 0;  // trials; trials with a positive difference grade
  double mean = 0;                       // of the difference grades
  std::optional<double> t, p_less;       // one-sided t-test; needs >= 2 trials that are not all equal
};

struct Bs1116Result {
  std::vector<Bs1116Assessor> assessors;  // in order of first appearance
  std::vector<MushraStat> conditions;     // difference grade over assessors, in order of first appearance
  std::size_t averaged = 0;               // assessor/condition cells with repeated trials
};

Bs1116Result bs1116_analyse(const std::vector<Bs1116Grade>& grades, double conf_level = 0.95);

// The grades of a tidy table, one row per trial: the export's bs1116.csv (participant, condition,
// diffgrade) or webMUSHRA's (session_uuid, rating_non_reference, rating_non_reference_score −
// rating_reference_score). InputError at the cell for a difference grade outside −4..4 or an empty name.
std::vector<Bs1116Grade> bs1116_from_table(const TidyCsv& table);

}  // namespace ms
