// Shuffle groups: neighbouring blocks that share a `shuffle` group run in an order drawn per
// participant (webMUSHRA's random page groups); groups that are not one run, or that meet a Latin
// square, are located problems.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/schedule.hpp"
#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"

namespace {

using ms::test::TempDir;

const std::string kHead =
    "study: t\ntitle: T\nseed: 7\nstimuli:\n"
    "  a: {file: a.wav}\n"
    "  b: {file: b.wav}\n";

const std::string kGrouped =
    kHead + "blocks:\n"
            "  - {type: instructions, id: hello, text: Hi.}\n"
            "  - {type: identify, id: one, stimuli: [a, b], labels: [a, b], shuffle: g}\n"
            "  - {type: identify, id: two, stimuli: [a, b], labels: [a, b], shuffle: g}\n"
            "  - {type: identify, id: three, stimuli: [a, b], labels: [a, b], shuffle: g}\n"
            "  - {type: instructions, id: bye, text: Bye.}\n";

std::vector<std::string> problems(const TempDir& dir, const std::string& text) {
  for (const char* name : {"a.wav", "b.wav"})
    ms::write_wav(dir.file(name), ms::Audio{44100, 1, std::vector<float>(441, 0.1f)}, ms::SampleFormat::float32);
  return ms::check_protocol_file(dir.write("p.yaml", text), {}).problems;
}

std::vector<std::size_t> order(const ms::Protocol& p, const std::string& participant) {
  return ms::make_schedule(p, participant).block_order;
}

}  // namespace

TEST(ShuffleGroups, AGroupsBlocksTakeAnOrderPerParticipantAndTheRestStayInPlace) {
  TempDir dir;
  ASSERT_TRUE(problems(dir, kGrouped).empty());
  const ms::Protocol p = ms::parse_protocol(kGrouped, "p.yaml", dir.path().string());
  EXPECT_EQ(p.blocks[1].shuffle, "g");
  std::set<std::vector<std::size_t>> seen;
  for (int k = 0; k < 60; ++k) {
    const std::vector<std::size_t> o = order(p, "P" + std::to_string(k));
    EXPECT_EQ(o.front(), 0u);
    EXPECT_EQ(o.back(), 4u);
    EXPECT_TRUE(std::is_permutation(o.begin() + 1, o.end() - 1, std::vector<std::size_t>{1, 2, 3}.begin()));
    seen.insert(o);
    EXPECT_EQ(o, order(p, "P" + std::to_string(k)));  // the same participant, the same order (resume)
  }
  EXPECT_EQ(seen.size(), 6u);  // all 3! orders occur among 60 participants
}

TEST(ShuffleGroups, EachBlockKeepsItsTrialsAndTheyRunTogetherInTheDrawnOrder) {
  TempDir dir;
  std::string plain = kGrouped;
  for (std::size_t at; (at = plain.find(", shuffle: g")) != std::string::npos;) plain.erase(at, 12);
  const ms::Protocol grouped = ms::parse_protocol(kGrouped, "p.yaml", dir.path().string());
  const ms::Protocol written = ms::parse_protocol(plain, "p.yaml", dir.path().string());
  EXPECT_EQ(ms::make_schedule(written, "P1").block_order, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  for (int k = 0; k < 10; ++k) {
    const ms::Schedule a = ms::make_schedule(grouped, "P" + std::to_string(k));
    const ms::Schedule b = ms::make_schedule(written, "P" + std::to_string(k));
    ASSERT_EQ(a.trials.size(), b.trials.size());
    // The blocks' trials follow block_order, each block's trials in one run with its own stimuli.
    std::vector<std::size_t> runs;
    for (const ms::Trial& t : a.trials)
      if (runs.empty() || runs.back() != t.block) runs.push_back(t.block);
    EXPECT_EQ(runs, a.block_order);
    auto stimuli_of = [](const ms::Schedule& s, std::size_t block) {
      std::multiset<std::vector<std::string>> out;
      for (const ms::Trial& t : s.trials)
        if (t.block == block) out.insert(t.stimuli);
      return out;
    };
    for (std::size_t block = 0; block < 5; ++block) EXPECT_EQ(stimuli_of(a, block), stimuli_of(b, block));
  }
}

TEST(ShuffleGroups, AGroupInterruptedByAnotherBlockIsALocatedProblem) {
  TempDir dir;
  std::string text = kGrouped;
  text.erase(text.find(", shuffle: g", text.find("id: two")), 12);
  const auto p = problems(dir, text);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find(dir.file("p.yaml") + ":11:"), std::string::npos) << p[0];
  EXPECT_NE(p[0].find("must be one run of neighbouring blocks"), std::string::npos) << p[0];
}

TEST(ShuffleGroups, AGroupAndALatinSquareTogetherAreALocatedProblem) {
  TempDir dir;
  std::string text = kGrouped;
  text.replace(text.find("seed: 7\n"), 8, "seed: 7\ncounterbalance: latin_square\n");
  const auto p = problems(dir, text);
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("use one of them"), std::string::npos) << p[0];
}
