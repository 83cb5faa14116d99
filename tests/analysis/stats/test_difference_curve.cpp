// Fig. 4 of van den Doel et al. 2002 from magnitude ratings, by hand: each listener's mean rating of
// (reference, token) in either order plus the offset, then the mean and sd over listeners; the token's
// number of modes read from its identical pair; the refusals.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/stats/difference_curve.hpp"

namespace {

using ms::InputError;
using ms::TidyCsv;

const ms::MagnitudeColumns kColumns{"participant", "first", "second", "value"};

// The real sound "real" and tokens m1 (1 mode) and m9 (9 modes) on the 1-10 scale. p1 rates (real, m1)
// 10 and (m1, real) 8: mean 9; p2 rates it 10. (real, m9): p1 3, p2 2. Identical pairs carry the modes.
const char* kRatings =
    "participant,first,second,value,modes\n"
    "p1,real,m1,10,\n" "p1,m1,real,8,\n" "p1,real,m9,3,\n" "p1,m9,m9,1,9\n" "p1,m1,m1,1,1\n" "p1,m1,m9,7,\n"
    "p2,m9,real,2,\n" "p2,real,m1,10,\n" "p2,m9,m9,1,9\n" "p2,m1,m1,2,1\n" "p2,real,real,1,all\n";

TEST(DifferenceCurve, MeanPerListenerThenOverListenersWithTheOffset) {
  const auto curve = ms::difference_to_reference(TidyCsv::parse(kRatings, "m.csv"), kColumns, "real", -1.0, "modes");
  ASSERT_EQ(curve.size(), 2u);
  // Sorted by modes: m1 first. m1: p1 (10 + 8) / 2 - 1 = 8, p2 10 - 1 = 9: mean 8.5, sd sqrt(0.5).
  EXPECT_EQ(curve[0].token, "m1");
  EXPECT_EQ(curve[0].x, "1");
  EXPECT_EQ(curve[0].listeners, 2u);
  EXPECT_DOUBLE_EQ(curve[0].mean, 8.5);
  EXPECT_NEAR(curve[0].sd, std::sqrt(0.5), 1e-12);
  // m9: p1 3 - 1 = 2, p2 2 - 1 = 1: mean 1.5.
  EXPECT_EQ(curve[1].token, "m9");
  EXPECT_EQ(curve[1].x, "9");
  EXPECT_DOUBLE_EQ(curve[1].mean, 1.5);
  // Without an offset the ratings as given; without x the order of first appearance.
  const auto raw = ms::difference_to_reference(TidyCsv::parse(kRatings, "m.csv"), kColumns, "real", 0.0);
  EXPECT_EQ(raw[0].token, "m1");
  EXPECT_DOUBLE_EQ(raw[0].mean, 9.5);
  EXPECT_TRUE(raw[0].x.empty());
}

TEST(DifferenceCurve, Refusals) {
  const auto refusal = [](const std::string& text, const std::string& reference, const std::string& x) {
    try {
      ms::difference_to_reference(TidyCsv::parse(text, "m.csv"), kColumns, reference, -1.0, x);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refusal(kRatings, "recording", "").find("no row rates the reference 'recording'"), std::string::npos);
  // A token never rated against itself has no x.
  const std::string no_self = "participant,first,second,value,modes\np1,real,m1,10,\n";
  EXPECT_NE(refusal(no_self, "real", "modes").find("'m1' is never rated against itself"), std::string::npos);
  // Its identical pair says two different things.
  const std::string twice = "participant,first,second,value,modes\np1,real,m1,10,\np1,m1,m1,1,1\np2,m1,m1,1,2\n";
  const std::string e = refusal(twice, "real", "modes");
  EXPECT_NE(e.find("m.csv:4:"), std::string::npos) << e;
  EXPECT_NE(e.find("'2' for 'm1' here but '1' on line 3"), std::string::npos) << e;
  const std::string empty_x = "participant,first,second,value,modes\np1,real,m1,10,\np1,m1,m1,1,\n";
  EXPECT_NE(refusal(empty_x, "real", "modes").find("empty on the identical pair of 'm1'"), std::string::npos);
  const std::string bad = "participant,first,second,value,modes\np1,real,m1,ten,\n";
  EXPECT_NE(refusal(bad, "real", "").find("m.csv:2:"), std::string::npos);
}

}  // namespace
