// The summary of a group of A/B trials (one listener, one condition, ...) for each discrimination
// design (Macmillan & Creelman, Detection Theory, 2nd ed. 2005):
//   2AFC, ABX: k correct of n; exact binomial tests against chance (one-sided "above", two-sided,
//     Clopper-Pearson interval); d' = sqrt2 z(p_c) (2AFC) or the ABX differencing model.
//   yes-no: hits H = hits/signal trials, false alarms F = false alarms/noise trials;
//     d' = z(H) - z(F), criterion c = -(z(H) + z(F))/2 (ch. 2).
//   same-different: d' and the differencing criterion k from H and F (ch. 9).
//   preference: how often each of two options was chosen (others are ties) with the two-sided
//     binomial test of the first against 1/2 over the untied choices; a graded score (e.g. -3..+3):
//     n, mean, sample sd (Skandalou & Ireland 2017's Figs 5.2 and 5.3 plot these per group) and a
//     one-sample t-test against 0 where one is defined (two or more scores, not all equal). With a
//     subject column each subject's scores of a group are averaged first, so n counts subjects and
//     a listener's repeated answers are not counted as independent ones.
// d' and c use rates of 0 or 1 moved to 1/(2N) or 1 - 1/(2N) (Macmillan & Kaplan 1985); the
// reported rates are the raw ones.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "analysis/stats/binomial_test.hpp"
#include "analysis/stats/t_test.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {

enum class AbTask { two_afc, abx, yes_no, same_different, preference };

// The trials of one group, typed; only the vectors of the task are filled.
struct AbTrials {
  std::string group;               // the --by values joined by '/', "" for all rows
  std::size_t n = 0;               // trials
  std::vector<bool> correct;       // 2afc, abx
  std::vector<bool> signal, said_yes;  // yesno, same-different: signal trial; answered yes/different
  std::vector<std::string> choice;     // preference: the chosen option
  std::vector<double> score;           // preference: graded score (per subject when averaged)
  bool averaged = false;               // a subject had more than one score in the group
};

struct AbPreference {
  unsigned first = 0, second = 0, ties = 0;
  std::optional<BinomialTest> test;  // first of first + second against 1/2; none when both are 0
};

// A graded score of one group. The t-test is absent for a single score or scores that are all equal
// (its t would be 0/0 or infinite), so a group where every listener gave the same answer is still
// summarised.
struct AbScore {
  std::size_t n = 0;
  double mean = 0, sd = 0;      // sd with n - 1 (NaN for one score)
  std::optional<TTest> test;    // against 0
};

// Which side a score favours: +1 when its interval lies above 0 (the second of the pair, B), -1 below
// (the first, A), 0 when it contains 0 ("both", as Table 5.3 says for ceramic). Two or more scores
// that are all equal favour the side of their value (every listener chose it); one score favours none.
int favoured_side(const AbScore& score);

struct AbSummary {
  std::string group;
  std::size_t n = 0;
  // 2afc, abx
  unsigned correct = 0;
  double pc = 0;
  BinomialTest above_chance, two_sided;
  // yesno, same-different (counts as doubles, as rates are formed from them)
  double hits = 0, signal_trials = 0, false_alarms = 0, noise_trials = 0;
  double hit_rate = 0, false_alarm_rate = 0;
  std::optional<double> criterion_c, criterion_k;  // yesno; same-different
  double dprime = 0;                               // all but preference
  // preference
  std::optional<AbPreference> preference;  // with a choice column
  std::optional<AbScore> score;            // with a score column
  bool rates_corrected = false;            // a rate of 0 or 1 was moved for d'
};

struct AbSummaryOptions {
  double chance = 0.5;                    // 2afc, abx
  double conf_level = 0.95;
  std::vector<std::string> options;       // preference: the two options
};

AbSummary ab_summary(const AbTrials& trials, AbTask task, const AbSummaryOptions& options);

// Columns of an A/B table, one row per trial; only the task's are read.
struct AbColumns {
  std::vector<std::string> by;
  std::string correct;             // 2afc, abx: 1/0, true/false, yes/no, correct/incorrect
  std::string stimulus, response;  // yesno, same-different
  std::string target, yes;         // the stimulus value of signal trials; the response meaning yes
  std::string choice, score;       // preference: either or both
  std::string subject;             // score: average each subject's scores per group first ("" = rows)
};

// The groups of the table (in order of first appearance). InputError at the cell for a correct flag
// or score that does not parse (NA included: a bipolar export's response_oriented is NA only for
// answers that are not scores), and for a yes-no or same-different group without both signal and
// other trials; "no data rows"; "missing column".
std::vector<AbTrials> ab_trials_from_table(const TidyCsv& table, AbTask task, const AbColumns& columns);

}  // namespace ms
