// ab_proportions and magnitude_map: what the experimenter view draws for A/B and magnitude blocks.
// The binomial figures are R's binom.test(7, 10) (tests/data/psychophysics/binom_golden.csv).
#include <gtest/gtest.h>

#include <cmath>

#include "studyapp/core/block_summaries.hpp"
#include "studyapp/core/protocol_parser.hpp"

namespace {

ms::ResponseRow row(const std::string& block, const std::string& type, const std::string& participant,
                    const std::string& stimuli, const std::string& value) {
  ms::ResponseRow r;
  r.study = "s";
  r.participant_code = participant;
  r.participant = participant == "P1" ? 1 : 2;
  r.session = 1;
  r.block_id = block;
  r.block_type = type;
  r.stimuli_json = stimuli;
  r.value_json = value;
  return r;
}

}  // namespace

TEST(BlockSummaries, AbxProportionCorrectPerPairBothOrdersWithTheClopperPearsonInterval) {
  std::vector<ms::ResponseRow> rows;
  // 10 ABX trials of metal/glass in both orders, 7 correct (X = B: "B" is right).
  for (int i = 0; i < 10; ++i) {
    const bool swap = i % 2 == 1;
    rows.push_back(row("abx", "ab", "P1", swap ? R"(["glass","metal","metal"])" : R"(["metal","glass","glass"])",
                       i < 7 ? R"("B")" : R"("A")"));
  }
  rows.push_back(row("other", "ab", "P1", R"(["metal","glass","glass"])", R"("A")"));  // another block
  const auto p = ms::ab_proportions(rows, "abx");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].first, "metal");
  EXPECT_EQ(p[0].second, "glass");
  EXPECT_EQ(p[0].measure, "correct");
  EXPECT_EQ(p[0].test.successes, 7);
  EXPECT_EQ(p[0].test.trials, 10);
  EXPECT_NEAR(p[0].test.p, 0.34375000000000011, 1e-12);
  EXPECT_NEAR(p[0].test.ci_low, 0.34754714994000269, 1e-9);
  EXPECT_NEAR(p[0].test.ci_high, 0.93326048882226553, 1e-9);
}

TEST(BlockSummaries, SameDifferentCountsDifferentAndChoicesCountTheFirstStimulusChosen) {
  std::vector<ms::ResponseRow> rows{row("sd", "ab", "P1", R"(["a","b"])", R"("different")"),
                                    row("sd", "ab", "P1", R"(["b","a"])", R"("same")"),
                                    row("sd", "ab", "P2", R"(["a","b"])", R"("different")"),
                                    row("pref", "ab", "P1", R"(["a","b"])", R"("A")"),
                                    row("pref", "ab", "P1", R"(["b","a"])", R"("B")"),
                                    row("pref", "ab", "P1", R"(["b","a"])", R"("A")"),
                                    row("bip", "ab", "P1", R"(["a","b"])", "2")};
  const auto sd = ms::ab_proportions(rows, "sd");
  ASSERT_EQ(sd.size(), 1u);
  EXPECT_EQ(sd[0].measure, "different");
  EXPECT_EQ(sd[0].test.successes, 2);
  EXPECT_EQ(sd[0].test.trials, 3);
  const auto pref = ms::ab_proportions(rows, "pref");
  ASSERT_EQ(pref.size(), 1u);
  EXPECT_EQ(pref[0].measure, "chose a");
  EXPECT_EQ(pref[0].test.successes, 2);  // A of (a, b) and B of (b, a)
  EXPECT_EQ(pref[0].test.trials, 3);
  EXPECT_TRUE(ms::ab_proportions(rows, "bip").empty());  // graded scores are no proportions
}

TEST(BlockSummaries, MagnitudeMapReproducesTheNormalisedDissimilaritiesWithTheProtocolsModulus) {
  const ms::Protocol protocol = ms::parse_protocol(
      "study: s\nstimuli:\n  a: {file: a.wav}\n  b: {file: b.wav}\n  c: {file: c.wav}\n"
      "blocks:\n  - {type: magnitude, id: mag, modulus: [a, b], modulus_value: 10, pairs: [[a, c], [b, c]]}\n",
      "p.yaml", ".");
  // P1 rates the modulus pair 20 (factor 10/20), P2 rates it 5 (factor 2): both then agree.
  std::vector<ms::ResponseRow> rows{
      row("mag", "magnitude", "P1", R"(["a","b"])", "20"), row("mag", "magnitude", "P1", R"(["a","c"])", "12"),
      row("mag", "magnitude", "P1", R"(["c","b"])", "16"), row("mag", "magnitude", "P2", R"(["b","a"])", "5"),
      row("mag", "magnitude", "P2", R"(["a","c"])", "3"),  row("mag", "magnitude", "P2", R"(["b","c"])", "4")};
  const ms::MagnitudeMap m = ms::magnitude_map(rows, "mag", &protocol);
  ASSERT_EQ(m.problem, "");
  ASSERT_EQ(m.labels, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(m.listeners, 2u);
  const auto dist = [&](std::size_t i, std::size_t j) { return std::hypot(m.x[i] - m.x[j], m.y[i] - m.y[j]); };
  EXPECT_NEAR(dist(0, 1), 10.0, 1e-9);  // the modulus pair stands for modulus_value
  EXPECT_NEAR(dist(0, 2), 6.0, 1e-9);
  EXPECT_NEAR(dist(1, 2), 8.0, 1e-9);
}

TEST(BlockSummaries, MagnitudeMapSaysWhyWhenAPairWasNeverRated) {
  std::vector<ms::ResponseRow> rows{row("mag", "magnitude", "P1", R"(["a","b"])", "20"),
                                    row("mag", "magnitude", "P1", R"(["a","c"])", "12"),
                                    row("mag", "magnitude", "P1", R"(["a","a"])", "0")};  // identical: left out
  const ms::MagnitudeMap m = ms::magnitude_map(rows, "mag", nullptr);
  EXPECT_TRUE(m.labels.empty());
  EXPECT_NE(m.problem.find("b"), std::string::npos) << m.problem;
  EXPECT_NE(m.problem.find("c"), std::string::npos) << m.problem;
  EXPECT_TRUE(ms::magnitude_map(rows, "none", nullptr).problem == "no magnitude responses");
}
