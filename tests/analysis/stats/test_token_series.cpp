// The adaptive token procedure of van den Doel et al. 2002 (Exp. 2) and its Table 2 summary, on series
// worked out by hand: which token is the reference after each answer, which tokens are distinguished,
// the counts with their ceilings and shares, and the located refusals of a table that does not follow
// the rule.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/stats/distinguished_tokens.hpp"
#include "analysis/stats/token_series.hpp"

namespace {

using ms::InputError;
using ms::TidyCsv;
using ms::TokenSeries;

// Six tokens (6 modes down to 1). Answers same, different, same, same, different:
//   compare 5 with 6: same          -> 5 discarded, the reference stays 6
//   compare 4 with 6: different     -> 4 becomes the reference
//   compare 3 with 4: same
//   compare 2 with 4: same
//   compare 1 with 4: different     -> 1 becomes the reference; the one-mode token was tested: done
// Distinguished: 6, 4, 1 (3 of a ceiling of 6).
TEST(TokenSeries, TheFirstDiscriminatedComparisonBecomesTheReference) {
  TokenSeries s(6, 1);
  EXPECT_EQ(s.tokens(), 6);
  const bool answers[] = {false, true, false, false, true};
  const int reference_before[] = {6, 6, 4, 4, 4}, compared[] = {5, 4, 3, 2, 1};
  for (int i = 0; i < 5; ++i) {
    ASSERT_FALSE(s.finished());
    EXPECT_EQ(s.reference(), reference_before[i]) << i;
    EXPECT_EQ(s.comparison(), compared[i]) << i;
    s.record(answers[i]);
  }
  EXPECT_TRUE(s.finished());
  EXPECT_EQ(s.reference(), 1);
  EXPECT_EQ(s.references(), (std::vector<int>{6, 6, 4, 4, 4}));
  EXPECT_EQ(s.comparisons(), (std::vector<int>{5, 4, 3, 2, 1}));
  EXPECT_EQ(s.distinguished(), (std::vector<int>{6, 4, 1}));
  EXPECT_THROW(s.record(true), std::logic_error);
}

TEST(TokenSeries, BoundsOfTheCount) {
  TokenSeries none(10, 3), all(10, 3);
  while (!none.finished()) none.record(false);
  while (!all.finished()) all.record(true);
  EXPECT_EQ(none.different().size(), 7u);                 // from - to comparisons whatever the answers
  EXPECT_EQ(none.distinguished(), std::vector<int>{10});  // the first reference only: 1
  EXPECT_EQ(all.distinguished().size(), 8u);              // every token: the ceiling, from - to + 1
  EXPECT_EQ(all.tokens(), 8);
  EXPECT_THROW(TokenSeries(3, 3), std::invalid_argument);
  EXPECT_THROW(TokenSeries(3, 0), std::invalid_argument);
}

// tokens.csv as the export writes it: two participants, two sequences of unequal ceilings (6 and 4
// tokens). p1: sequence a as above (3 of 6), b all different (4 of 4); p2: a all same (1 of 6), b
// same, different, same (2 of 4).
const char* kTokens =
    "participant,block,trial,reference,comparison,different\n"
    "p1,a,0,6,5,0\n" "p1,a,0,6,4,1\n" "p1,a,0,4,3,0\n" "p1,a,0,4,2,0\n" "p1,a,0,4,1,1\n"
    "p1,b,0,4,3,1\n" "p1,b,0,3,2,1\n" "p1,b,0,2,1,1\n"
    "p2,a,0,6,5,0\n" "p2,a,0,6,4,0\n" "p2,a,0,6,3,0\n" "p2,a,0,6,2,0\n" "p2,a,0,6,1,0\n"
    "p2,b,0,4,3,0\n" "p2,b,0,4,2,1\n" "p2,b,0,2,1,0\n";

TEST(DistinguishedTokens, CountsCeilingsAndSharesByHand) {
  const auto counts = ms::token_counts_from_table(TidyCsv::parse(kTokens, "tokens.csv"), {});
  ASSERT_EQ(counts.size(), 4u);
  EXPECT_EQ(counts[0].distinguished, 3);
  EXPECT_EQ(counts[0].tokens, 6);
  EXPECT_EQ(counts[1].distinguished, 4);
  EXPECT_EQ(counts[1].tokens, 4);
  EXPECT_EQ(counts[2].distinguished, 1);
  EXPECT_EQ(counts[3].distinguished, 2);
  const ms::TokensTable t = ms::tokens_table(counts);
  ASSERT_EQ(t.conditions, (std::vector<std::string>{"a", "b"}));
  ASSERT_EQ(t.participants, (std::vector<std::string>{"p1", "p2"}));
  EXPECT_EQ(t.count[0][0], 3);
  EXPECT_EQ(t.count[1][1], 2);
  EXPECT_DOUBLE_EQ(t.share[0][1], 1.0);   // 4 of 4
  EXPECT_DOUBLE_EQ(t.share[1][0], 1.0 / 6.0);
  EXPECT_EQ(t.summary[0].tokens_min, 6);
  EXPECT_EQ(t.summary[1].tokens_max, 4);
  EXPECT_DOUBLE_EQ(t.summary[0].median, 2.0);        // (3 + 1) / 2
  EXPECT_DOUBLE_EQ(t.summary[1].median, 3.0);        // (4 + 2) / 2
  EXPECT_DOUBLE_EQ(t.summary[0].median_share, (0.5 + 1.0 / 6.0) / 2);
  EXPECT_DOUBLE_EQ(t.summary[1].median_share, 0.75);  // (1 + 0.5) / 2
  EXPECT_EQ(t.summary[0].min, 1);
  EXPECT_EQ(t.summary[0].max, 3);
}

TEST(DistinguishedTokens, RepeatedSeriesAreAveragedPerParticipant) {
  const char* two = "participant,block,trial,reference,comparison,different\n"
                    "p1,a,0,3,2,1\n" "p1,a,0,2,1,1\n"   // 3 of 3
                    "p1,a,1,3,2,0\n" "p1,a,1,3,1,0\n";  // 1 of 3
  const ms::TokensTable t = ms::tokens_table(ms::token_counts_from_table(TidyCsv::parse(two, "t.csv"), {}));
  EXPECT_EQ(t.series[0][0], 2u);
  EXPECT_DOUBLE_EQ(t.count[0][0], 2.0);
  EXPECT_DOUBLE_EQ(t.share[0][0], 2.0 / 3.0);
}

std::string refusal(const std::string& text) {
  try {
    ms::token_counts_from_table(TidyCsv::parse(text, "t.csv"), {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DistinguishedTokens, RowsThatBreakTheRuleAreRefusedAtTheirCell) {
  const std::string head = "participant,block,trial,reference,comparison,different\n";
  // The comparison skips a token.
  std::string e = refusal(head + "p1,a,0,6,5,0\np1,a,0,6,3,0\n");
  EXPECT_NE(e.find("t.csv:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("compares 4 modes here"), std::string::npos) << e;
  // After "different" at 5, the reference must be 5.
  e = refusal(head + "p1,a,0,6,5,1\np1,a,0,6,4,0\n");
  EXPECT_NE(e.find("t.csv:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("make 5 modes the reference"), std::string::npos) << e;
  e = refusal(head + "p1,a,0,6,5,yes\n");
  EXPECT_NE(e.find("expected 1 (different) or 0 (same)"), std::string::npos) << e;
  e = refusal(head + "p1,a,0,2,1,0\np1,a,0,2,0,0\n");
  EXPECT_NE(e.find("more than its first reference's 2 modes allow"), std::string::npos) << e;
  e = refusal(head + "p1,a,0,2.5,1,0\n");
  EXPECT_NE(e.find("whole number"), std::string::npos) << e;
  e = refusal(head);
  EXPECT_NE(e.find("no data rows"), std::string::npos) << e;
}

}  // namespace
