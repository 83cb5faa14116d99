// Table 2 of van den Doel et al. 2002: the number of tokens each listener distinguished in each
// sequence (object x mode order), from the comparisons of the adaptive token procedure
// (token_series.hpp) as the export's tokens.csv holds them, one row per comparison.
//
// A count is only meaningful against its sequence's ceiling, the number of tokens (the paper's 179,
// 100, 128 and 41): a sequence of 41 tokens cannot give more than 41, so counts of two sequences differ
// by their ceilings before any listener is asked, and a paired test of counts across sequences (naive vs
// energy order) mixes the ordering's effect with the ceiling's. Each cell is therefore reported with its
// ceiling and its share of the ceiling.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

// One series as counted.
struct TokenCount {
  std::string series;        // the series columns' values joined by '/'
  std::string participant, condition;
  int distinguished = 0;     // references in turn, the first one included
  int tokens = 0;            // the ceiling: from - to + 1
};

// Column names of a table with one row per comparison, in presentation order within each series.
struct TokenColumns {
  std::vector<std::string> series{"participant", "block", "trial"};
  std::string participant = "participant";
  std::vector<std::string> condition{"block"};  // joined by '/' into the condition's name
  std::string reference = "reference", comparison = "comparison", different = "different";
};

// Replays each series with TokenSeries: the first row's reference is the sequence's first token, row i
// compares the token one mode below row i - 1's, and every reference must be the one the rule gives
// after the earlier answers. InputError at the cell otherwise (a comparison out of order, a reference
// the answers do not lead to, `different` not 0/1, a condition that changes within a series); "no
// data rows".
std::vector<TokenCount> token_counts_from_table(const TidyCsv& table, const TokenColumns& columns);

struct TokensCondition {
  std::string name;
  int tokens_min = 0, tokens_max = 0;  // the ceiling (equal unless the sequence changed between series)
  std::size_t participants = 0;
  double median = 0, min = 0, max = 0;  // of the participants' counts (each their mean over repeats)
  double median_share = 0;              // of the participants' count / ceiling
};

// Participants x conditions, both in order of first appearance. count[p][c] is the participant's mean
// count over their series of the condition (NaN when none), series[p][c] how many.
struct TokensTable {
  std::vector<std::string> participants, conditions;
  std::vector<std::vector<double>> count, share;
  std::vector<std::vector<std::size_t>> series;
  std::vector<TokensCondition> summary;  // one per condition
};

TokensTable tokens_table(const std::vector<TokenCount>& counts);

}  // namespace ms
