// Pair forms: A/B pairs with a per-pair reference ([a, b, ref]), refused in ABX and when mixed with
// plain pairs; magnitude `pairs: all_with_identical` (the 2002 study's 78 pairs of 12 sounds).
#include <gtest/gtest.h>

#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/schedule.hpp"
#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"

namespace {

using ms::test::TempDir;

// A real (short) recording: protocol check reads every recording as a session start does.
void write_recording(const ms::test::TempDir& dir, const std::string& name) {
  ms::write_wav(dir.file(name), ms::Audio{44100, 1, std::vector<float>(441, 0.1f)}, ms::SampleFormat::float32);
}

const std::string kHead = "study: t\nseed: 3\nstimuli:\n  a: {file: a.wav}\n  b: {file: b.wav}\n  r: {file: r.wav}\n";

std::vector<std::string> check(const TempDir& dir, const std::string& text) {
  for (const char* f : {"a.wav", "b.wav", "r.wav"}) write_recording(dir, f);
  return ms::check_protocol_file(dir.write("p.yaml", text)).problems;
}

TEST(ProtocolPairs, TriplesAddTheReferenceAfterAAndB) {
  TempDir dir;
  ASSERT_TRUE(check(dir, kHead + "blocks:\n  - {type: ab, id: m, mode: bipolar, pairs: [[a, b, r], [b, a, r]], repeats: 2}\n")
                  .empty());
  const ms::Protocol p = ms::load_protocol(dir.file("p.yaml"));
  const auto s = ms::make_schedule(p, "P1");
  ASSERT_EQ(s.trials.size(), 4u);
  for (const auto& t : s.trials) {
    ASSERT_EQ(t.stimuli.size(), 3u);
    EXPECT_EQ(t.stimuli[2], "r");
    EXPECT_EQ(t.reference, "r");
  }
}

TEST(ProtocolPairs, TriplesAreRefusedInAbxAndWhenMixed) {
  TempDir dir;
  const auto abx = check(dir, kHead + "blocks:\n  - {type: ab, id: x, mode: abx, pairs: [[a, b, r]]}\n");
  ASSERT_GE(abx.size(), 1u);  // (the skipped block then leaves the protocol without blocks)
  EXPECT_NE(abx[0].find("p.yaml:8:"), std::string::npos) << abx[0];
  EXPECT_NE(abx[0].find("ABX plays X"), std::string::npos) << abx[0];
  const auto mixed = check(dir, kHead + "blocks:\n  - {type: ab, id: m, mode: bipolar, pairs: [[a, b, r], [a, b]]}\n");
  ASSERT_GE(mixed.size(), 1u);
  EXPECT_NE(mixed[0].find("every one as [a, b, reference]"), std::string::npos) << mixed[0];
  const auto missing = check(dir, kHead + "blocks:\n  - {type: ab, id: m, mode: bipolar, pairs: [[a, b, rr]]}\n");
  ASSERT_FALSE(missing.empty());
  EXPECT_NE(missing[0].find("'rr'"), std::string::npos) << missing[0];
}

TEST(ProtocolPairs, MagnitudeAllWithIdentical) {
  TempDir dir;
  ASSERT_TRUE(check(dir, kHead + "blocks:\n  - {type: magnitude, id: g, modulus: [a, b], pairs: all_with_identical,"
                                 " stimuli: [a, b, r]}\n")
                  .empty());
  const auto s = ms::make_schedule(ms::load_protocol(dir.file("p.yaml")), "P1");
  ASSERT_EQ(s.trials.size(), 6u);  // 3 distinct + 3 identical
  std::size_t identical = 0;
  for (const auto& t : s.trials) identical += t.stimuli[0] == t.stimuli[1];
  EXPECT_EQ(identical, 3u);
}

}  // namespace
