// read_magnitude: decimal point or comma, refusals with their reason, 0 only with identical pairs.
#include <gtest/gtest.h>

#include "studyapp/core/magnitude_input.hpp"

TEST(MagnitudeInput, DecimalPointAndCommaGiveTheSameNumber) {
  EXPECT_DOUBLE_EQ(*ms::read_magnitude("12.5", false).value, 12.5);
  EXPECT_DOUBLE_EQ(*ms::read_magnitude("12,5", false).value, 12.5);
  EXPECT_DOUBLE_EQ(*ms::read_magnitude(" 200 ", false).value, 200.0);
  EXPECT_DOUBLE_EQ(*ms::read_magnitude(",5", false).value, 0.5);
}

TEST(MagnitudeInput, NothingTypedIsNoValueAndNoComplaint) {
  const ms::MagnitudeEntry e = ms::read_magnitude("  ", false);
  EXPECT_FALSE(e.value.has_value());
  EXPECT_TRUE(e.problem.empty());
}

TEST(MagnitudeInput, RefusalsSayWhy) {
  EXPECT_EQ(ms::read_magnitude("abc", false).problem, "'abc' is not a number: type digits only, e.g. 50 or 12,5.");
  EXPECT_EQ(ms::read_magnitude("1,234.5", false).problem,
            "Write one number with at most one decimal mark, e.g. 12.5 or 12,5.");
  EXPECT_EQ(ms::read_magnitude("-3", true).problem, "The number cannot be negative: 0 would mean no difference at all.");
  EXPECT_EQ(ms::read_magnitude("1e3", false).problem.substr(0, 5), "'1e3'");
  EXPECT_FALSE(ms::read_magnitude("12.5x", false).value.has_value());
}

TEST(MagnitudeInput, ZeroOnlyWhereIdenticalPairsAreAsked) {
  const ms::MagnitudeEntry refused = ms::read_magnitude("0", false);
  EXPECT_FALSE(refused.value.has_value());
  EXPECT_EQ(refused.problem, "Type a number above 0: every pair here differs at least a little.");
  EXPECT_DOUBLE_EQ(*ms::read_magnitude("0", true).value, 0.0);
  EXPECT_DOUBLE_EQ(*ms::read_magnitude("0,0", true).value, 0.0);
}

#include "studyapp/core/response_format.hpp"

TEST(MagnitudeInput, SessionAcceptsZeroOnlyWithIdenticalPairs) {
  ms::Block b;
  b.type = ms::BlockType::magnitude;
  ms::MagnitudeBlock body;
  b.body = body;
  EXPECT_NE(ms::check_answer(b, ms::Trial{}, 0.0), "");
  EXPECT_EQ(ms::check_answer(b, ms::Trial{}, 12.5), "");
  body.all_pairs = body.identical_pairs = true;
  b.body = body;
  EXPECT_EQ(ms::check_answer(b, ms::Trial{}, 0.0), "");
  EXPECT_NE(ms::check_answer(b, ms::Trial{}, -1.0), "");
}
