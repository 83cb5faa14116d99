// ab_summary against golden values from the Python standard library (tests/data/ab_summary/golden.py),
// and ab_trials_from_table on the rows it builds them from.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "analysis/stats/ab_summary.hpp"

using namespace ms;

namespace {

nlohmann::json golden() {
  std::ifstream in(std::string(MODALSTUDY_TEST_DATA) + "/ab_summary/golden.json");
  return nlohmann::json::parse(in);
}

AbTrials detection(int signal, int hits, int noise, int fas) {
  AbTrials t;
  for (int i = 0; i < signal; ++i) t.signal.push_back(true), t.said_yes.push_back(i < hits);
  for (int i = 0; i < noise; ++i) t.signal.push_back(false), t.said_yes.push_back(i < fas);
  t.n = t.signal.size();
  return t;
}

}  // namespace

TEST(AbSummary, YesNoCountsHitsFalseAlarmsDprimeAndCriterion) {
  const auto g = golden()["yesno"];
  const AbSummary s = ab_summary(detection(10, 7, 10, 2), AbTask::yes_no, {});
  EXPECT_EQ(s.hits, g["hits"].get<double>());
  EXPECT_EQ(s.false_alarms, g["false_alarms"].get<double>());
  EXPECT_DOUBLE_EQ(s.hit_rate, 0.7);
  EXPECT_DOUBLE_EQ(s.false_alarm_rate, 0.2);
  EXPECT_NEAR(s.dprime, g["dprime"].get<double>(), 1e-9);
  ASSERT_TRUE(s.criterion_c);
  EXPECT_NEAR(*s.criterion_c, g["criterion_c"].get<double>(), 1e-9);
  EXPECT_FALSE(s.rates_corrected);
}

TEST(AbSummary, YesNoPerfectHitRateIsCorrectedForDprime) {
  const auto g = golden()["yesno_corrected"];
  const AbSummary s = ab_summary(detection(8, 8, 8, 3), AbTask::yes_no, {});
  EXPECT_TRUE(s.rates_corrected);
  EXPECT_DOUBLE_EQ(s.hit_rate, 1.0);  // reported raw
  EXPECT_NEAR(s.dprime, g["dprime"].get<double>(), 1e-9);
  EXPECT_NEAR(*s.criterion_c, g["criterion_c"].get<double>(), 1e-9);
}

TEST(AbSummary, TwoAfcProportionDprimeAndExactTest) {
  const auto g = golden()["2afc"];
  AbTrials t;
  for (int i = 0; i < 20; ++i) t.correct.push_back(i < 15);
  t.n = 20;
  const AbSummary s = ab_summary(t, AbTask::two_afc, {});
  EXPECT_EQ(s.correct, g["correct"].get<unsigned>());
  EXPECT_DOUBLE_EQ(s.pc, g["pc"].get<double>());
  EXPECT_NEAR(s.dprime, g["dprime"].get<double>(), 1e-9);
  EXPECT_NEAR(s.above_chance.p, g["p_above_chance"].get<double>(), 1e-12);
}

TEST(AbSummary, PreferenceCountsTiesAndTestsTheUntiedChoices) {
  const auto g = golden()["preference"];
  AbTrials t;
  t.choice = {"A", "A", "B", "A", "tie", "A", "A", "B", "none", "A"};
  t.n = t.choice.size();
  const AbSummary s = ab_summary(t, AbTask::preference, {0.5, 0.95, {"A", "B"}});
  ASSERT_TRUE(s.preference);
  EXPECT_EQ(s.preference->first, g["first"].get<unsigned>());
  EXPECT_EQ(s.preference->second, g["second"].get<unsigned>());
  EXPECT_EQ(s.preference->ties, g["ties"].get<unsigned>());
  ASSERT_TRUE(s.preference->test);
  EXPECT_NEAR(s.preference->test->p, g["p"].get<double>(), 1e-12);
  EXPECT_FALSE(s.score);
}

TEST(AbSummary, FromTableGroupsAndTypesTheRows) {
  const TidyCsv t = TidyCsv::parse("who,stim,ans\np1,signal,yes\np1,noise,no\np2,signal,no\np2,noise,yes\n", "ab.csv");
  AbColumns c;
  c.by = {"who"};
  c.stimulus = "stim";
  c.response = "ans";
  c.target = "signal";
  c.yes = "yes";
  const auto groups = ab_trials_from_table(t, AbTask::yes_no, c);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[1].group, "p2");
  EXPECT_EQ(groups[1].signal, (std::vector<bool>{true, false}));
  EXPECT_EQ(groups[1].said_yes, (std::vector<bool>{false, true}));
}

TEST(AbSummary, FromTableNamesFileAndColumn) {
  const TidyCsv t = TidyCsv::parse("who,correct\np1,1\np1,maybe\n", "afc.csv");
  AbColumns c;
  c.correct = "correct";
  try {
    ab_trials_from_table(t, AbTask::two_afc, c);
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("afc.csv:3:4: column 'correct'"), std::string::npos) << e.what();
  }
  c.correct = "ok";
  EXPECT_THROW(ab_trials_from_table(t, AbTask::two_afc, c), InputError);
}
