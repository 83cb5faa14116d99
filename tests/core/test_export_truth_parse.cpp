// Protocol stimuli's `truth:` and `factors:` maps (read by the export's truth and factor columns).
#include <gtest/gtest.h>

#include "studyapp/core/protocol_parser.hpp"
#include "synthesis/input_error.hpp"

namespace {

const std::string kHead = "study: t\ntitle: T\nstimuli:\n";
const std::string kTail = "blocks:\n  - {type: identify, id: material, stimuli: [a], labels: [metal, wood]}\n";

}  // namespace

TEST(ProtocolTruth, TruthAndFactorsAreReadInFileOrder) {
  const auto p = ms::parse_protocol(
      kHead +
          "  a: {file: a.wav, truth: {shape: disc, material: metal}, factors: {dataset: emg, shape: disc, "
          "material: metal}}\n"
          "  b: {derive: a, lowpass_hz: 3500, truth: wood}\n" + kTail,
      "p.yaml", ".");
  const ms::StimulusSource* a = p.find_stimulus("a");
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->truth.size(), 2u);
  EXPECT_EQ(a->truth[0], (std::pair<std::string, std::string>{"shape", "disc"}));
  EXPECT_EQ(a->truth[1], (std::pair<std::string, std::string>{"material", "metal"}));
  ASSERT_EQ(a->factors.size(), 3u);
  EXPECT_EQ(a->factors[0].first, "dataset");
  EXPECT_EQ(a->factors[2].second, "metal");
  const ms::StimulusSource* b = p.find_stimulus("b");
  ASSERT_NE(b, nullptr);
  ASSERT_EQ(b->truth.size(), 1u);
  EXPECT_EQ(b->truth[0], (std::pair<std::string, std::string>{"", "wood"}));
  EXPECT_TRUE(b->factors.empty());
}

TEST(ProtocolTruth, FactorsThatAreNotAFlatMapNameLineAndColumn) {
  try {
    ms::parse_protocol(kHead + "  a: {file: a.wav, factors: [emg, disc]}\n" + kTail, "p.yaml", ".");
    FAIL() << "a list of factors was accepted";
  } catch (const ms::InputError& e) {
    EXPECT_EQ(e.where().file, "p.yaml");
    EXPECT_EQ(e.where().line, 4);
    EXPECT_GT(e.where().column, 1);
    EXPECT_NE(std::string(e.what()).find("expected a map name -> label"), std::string::npos) << e.what();
  }
  try {
    ms::parse_protocol(kHead + "  a: {file: a.wav, truth: {material: {x: 1}}}\n" + kTail, "p.yaml", ".");
    FAIL() << "a nested truth was accepted";
  } catch (const ms::InputError& e) {
    EXPECT_EQ(e.where().line, 4);
    EXPECT_NE(std::string(e.what()).find("truth.material"), std::string::npos) << e.what();
  }
}

TEST(ProtocolTruth, MisspelledKeySuggestsTruth) {
  try {
    ms::parse_protocol(kHead + "  a: {file: a.wav, turth: metal}\n" + kTail, "p.yaml", ".");
    FAIL() << "an unknown key was accepted";
  } catch (const ms::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("truth"), std::string::npos) << e.what();
  }
}
