// The table-to-rows readers beside each statistic: typed rows from a tidy CSV, InputError naming the
// file and column for a wrong or missing column, and a pandas-style file (BOM, quoted cells, CRLF)
// read the same as a plain one.
#include <gtest/gtest.h>

#include <string>

#include "analysis/stats/confusion.hpp"
#include "analysis/stats/method_of_limits.hpp"
#include "analysis/stats/mushra.hpp"
#include "analysis/stats/staircase.hpp"
#include "analysis/stats/t_test.hpp"

using namespace ms;

namespace {

// The message of the InputError `f` throws, "" when it throws none.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kMushra = "participant,trial,condition,rating\np1,t1,reference,100\np1,t1,anchor35,20\n"
                            "p2,t1,reference,95\np2,t1,anchor35,30\n";
const std::string kMushraPandas = "\xEF\xBB\xBF\"participant\",\"trial\",\"condition\",\"rating\"\r\n"
                                  "\"p1\",\"t1\",\"reference\",100\r\n\"p1\",\"t1\",\"anchor35\",20\r\n"
                                  "\"p2\",\"t1\",\"reference\",95\r\n\"p2\",\"t1\",\"anchor35\",30\r\n";

}  // namespace

TEST(StatsFromTable, MushraRatingsAndDefaultAnchors) {
  const MushraTable m = mushra_from_table(TidyCsv::parse(kMushra, "m.csv"), {}, {});
  ASSERT_EQ(m.ratings.size(), 4u);
  EXPECT_EQ(m.ratings[3].subject, "p2");
  EXPECT_EQ(m.ratings[3].condition, "anchor35");
  EXPECT_DOUBLE_EQ(m.ratings[3].rating, 30);
  EXPECT_EQ(m.options.anchors, std::vector<std::string>{"anchor35"});
}

TEST(StatsFromTable, MushraPandasFileReadsTheSame) {
  const MushraTable a = mushra_from_table(TidyCsv::parse(kMushra, "m.csv"), {}, {});
  const MushraTable b = mushra_from_table(TidyCsv::parse(kMushraPandas, "p.csv"), {}, {});
  ASSERT_EQ(a.ratings.size(), b.ratings.size());
  for (std::size_t i = 0; i < a.ratings.size(); ++i) {
    EXPECT_EQ(a.ratings[i].subject, b.ratings[i].subject);
    EXPECT_EQ(a.ratings[i].condition, b.ratings[i].condition);
    EXPECT_EQ(a.ratings[i].rating, b.ratings[i].rating);
  }
}

TEST(StatsFromTable, MushraMissingColumnNamesFileAndColumn) {
  const std::string e = error_of([] { mushra_from_table(TidyCsv::parse(kMushra, "m.csv"), {"", "", "", "score"}, {}); });
  EXPECT_NE(e.find("m.csv:1:1: missing column 'score'"), std::string::npos) << e;
}

TEST(StatsFromTable, ConfusionPairsAndLabelOutsideList) {
  const TidyCsv t = TidyCsv::parse("truth,answer\nwood,wood\nglass,wood\n", "c.csv");
  const ConfusionResponses r = confusion_responses_from_table(t, "truth", "answer", {});
  EXPECT_EQ(r.truth, (std::vector<std::string>{"wood", "glass"}));
  EXPECT_EQ(r.response, (std::vector<std::string>{"wood", "wood"}));
  const std::string e = error_of([&] { confusion_responses_from_table(t, "truth", "answer", {"wood"}); });
  EXPECT_NE(e.find("c.csv:3:1: column 'truth': label 'glass' is not in --labels"), std::string::npos) << e;
  EXPECT_NE(error_of([&] { confusion_responses_from_table(t, "truth", "reply", {}); }).find("c.csv:1:1: missing column 'reply'"),
            std::string::npos);
}

TEST(StatsFromTable, TTestPairedAveragesPerSubject) {
  const TidyCsv t = TidyCsv::parse("s,g,v\na,x,1\na,y,2\na,x,3\nb,x,5\nb,y,4\n", "t.csv");
  const TTestSamples x = t_test_samples_from_table(t, {"v", "g", "s", true});
  EXPECT_EQ(x.levels, (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(x.first, (std::vector<double>{2, 5}));
  EXPECT_EQ(x.second, (std::vector<double>{2, 4}));
  EXPECT_TRUE(x.averaged);
  const std::string e = error_of([&] { t_test_samples_from_table(t, {"v", "g", "subject", true}); });
  EXPECT_NE(e.find("t.csv:1:1: missing column 'subject'"), std::string::npos) << e;
}

TEST(StatsFromTable, StaircaseTracksOrderedByTrial) {
  const TidyCsv t = TidyCsv::parse("who,step,level,next_level\np,1,8,6\np,0,10,8\nq,0,5,4\n", "s.csv");
  const StaircaseTracks s = staircase_tracks_from_table(t, {"level", "step", "next_level", {"who"}}, false);
  ASSERT_EQ(s.tracks.size(), 2u);
  EXPECT_TRUE(s.has_next_level);
  EXPECT_EQ(s.tracks[0].levels, (std::vector<double>{10, 8}));
  EXPECT_EQ(s.tracks[0].next_level, 6.0);
  const std::string e = error_of([&] { staircase_tracks_from_table(t, {"lvl", "", "", {}}, false); });
  EXPECT_NE(e.find("s.csv:1:1: missing column 'lvl'"), std::string::npos) << e;
}

TEST(StatsFromTable, LimitsSeriesMustFall) {
  const TidyCsv t = TidyCsv::parse("who,db,answer\np,20,same\np,18,different\nq,20,same\nq,21,same\n", "l.csv");
  LimitsColumns c{"db", "answer", "different", {}};
  const std::string e = error_of([&] { limits_series_from_table(t, c); });
  EXPECT_NE(e.find("l.csv:4:3: column 'db': level 20 does not fall"), std::string::npos) << e;
  c.track = {"who"};
  EXPECT_THROW(limits_series_from_table(t, c), InputError);  // q rises
  const auto s = limits_series_from_table(TidyCsv::parse("db,answer\n20,same\n18,different\n", "ok.csv"), c = {"db", "answer", "different", {}});
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].different, (std::vector<bool>{false, true}));
}
