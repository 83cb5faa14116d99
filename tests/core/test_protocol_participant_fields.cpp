// The protocol fields the participant's views read: a block's `prompt`, `listen_all` (default on for every
// block type), `feedback`, an adjust block's `target` and each slider's `label`/`low`/`high`/`show_value`.
#include <gtest/gtest.h>

#include <algorithm>

#include "studyapp/core/protocol_parser.hpp"
#include "synthesis/input_error.hpp"

namespace {

const std::string kHead =
    "study: t\nstimuli:\n"
    "  a: {file: a.wav}\n"
    "  b: {file: b.wav}\n"
    "blocks:\n";

ms::Protocol parse(const std::string& blocks) { return ms::parse_protocol(kHead + blocks, "p.yaml", "."); }

std::string error_of(const std::string& blocks) {
  try {
    parse(blocks);
  } catch (const ms::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ProtocolParticipantFields, ListenAllIsOnByDefaultForEveryBlockTypeAndCanBeTurnedOff) {
  const ms::Protocol p = parse(
      "  - {type: ab, pairs: [[a, b]]}\n"
      "  - {type: ab, mode: abx, pairs: [[a, b]], listen_all: false}\n"
      "  - {type: identify, stimuli: [a], labels: [x, y], listen_all: no}\n"
      "  - {type: magnitude, modulus: [a, b], stimuli: [a, b]}\n"
      "  - {type: staircase, stimulus: a, parameter: p, start: 1, step: -1, listen_all: false}\n");
  ASSERT_EQ(p.blocks.size(), 5u);
  EXPECT_TRUE(p.blocks[0].listen_all);
  EXPECT_FALSE(p.blocks[1].listen_all);
  EXPECT_FALSE(p.blocks[2].listen_all);
  EXPECT_TRUE(p.blocks[3].listen_all);
  EXPECT_FALSE(p.blocks[4].listen_all);
}

TEST(ProtocolParticipantFields, PromptAndFeedbackOnAnyBlock) {
  const ms::Protocol p = parse(
      "  - {type: ab, training: true, feedback: true, prompt: \"Do the two taps come from the same object?\", "
      "pairs: [[a, b]]}\n"
      "  - {type: questionnaire, prompt: \"Last questions\", questions: [\"Comments?\"]}\n"
      "  - {type: identify, stimuli: [a], labels: [x]}\n");
  EXPECT_EQ(p.blocks[0].prompt, "Do the two taps come from the same object?");
  EXPECT_TRUE(p.blocks[0].feedback);
  EXPECT_EQ(p.blocks[1].prompt, "Last questions");
  EXPECT_TRUE(p.blocks[2].prompt.empty());
  EXPECT_FALSE(p.blocks[2].feedback);
}

TEST(ProtocolParticipantFields, AdjustTargetAndSliderLabels) {
  const ms::Protocol p = parse(
      "  - type: adjust\n"
      "    paramset: a\n"
      "    target: b\n"
      "    sliders:\n"
      "      - {key: damping.alpha1, min: 0.5, max: 10, label: Ringing, low: long, high: short, show_value: true}\n"
      "      - {key: damping.alpha2, min: 0, max: 1}\n");
  const auto& adjust = std::get<ms::AdjustBlock>(p.blocks[0].body);
  ASSERT_TRUE(adjust.target.has_value());
  EXPECT_EQ(adjust.target->name, "b");
  EXPECT_EQ(adjust.target->where.line, 8);
  ASSERT_EQ(adjust.sliders.size(), 2u);
  EXPECT_EQ(adjust.sliders[0].label, "Ringing");
  EXPECT_EQ(adjust.sliders[0].low, "long");
  EXPECT_EQ(adjust.sliders[0].high, "short");
  EXPECT_TRUE(adjust.sliders[0].show_value);
  EXPECT_TRUE(adjust.sliders[1].label.empty());
  EXPECT_FALSE(adjust.sliders[1].show_value);
  const auto refs = p.blocks[0].referenced();  // the target is validated like every named stimulus
  EXPECT_TRUE(std::any_of(refs.begin(), refs.end(), [](const ms::StimulusRef& r) { return r.name == "b"; }));
}

TEST(ProtocolParticipantFields, BadValuesNameLineAndColumn) {
  EXPECT_EQ(error_of("  - {type: ab, feedback: maybe, pairs: [[a, b]]}\n"),
            "p.yaml:6:26: blocks[0].feedback: expected true or false, got 'maybe'");
  EXPECT_EQ(error_of("  - type: adjust\n    paramset: a\n    sliders:\n"
                     "      - {key: k, min: 0, max: 1, show_value: 2}\n"),
            "p.yaml:9:46: blocks[0].sliders[0].show_value: expected true or false, got '2'");
  const std::string unknown = error_of("  - type: adjust\n    paramset: a\n    sliders:\n"
                                       "      - {key: k, min: 0, max: 1, lable: Ringing}\n");
  EXPECT_NE(unknown.find("p.yaml:9:"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("label"), std::string::npos) << unknown;  // did you mean
}
