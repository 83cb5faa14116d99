// answer_gate: every block type waits for every sound (listen_all on by default), MUSHRA for every
// slider, and then for a complete answer; listen_all: false lifts the listening rules only.
#include <gtest/gtest.h>

#include "studyapp/core/answer_gate.hpp"

namespace {

ms::Block block(ms::BlockType type, bool listen_all = true) {
  ms::Block b;
  b.type = type;
  b.listen_all = listen_all;
  return b;
}

}  // namespace

TEST(AnswerGate, EveryListeningBlockTypeWaitsForEverySound) {
  for (const ms::BlockType type : {ms::BlockType::ab, ms::BlockType::mushra, ms::BlockType::magnitude,
                                   ms::BlockType::identify, ms::BlockType::rating, ms::BlockType::adjust,
                                   ms::BlockType::staircase}) {
    ms::TrialInputs in;
    in.heard = {true, false, true};
    in.moved = {true, true};
    in.complete = true;
    const ms::AnswerGate g = ms::answer_gate(block(type), in);
    EXPECT_FALSE(g.may_send) << ms::to_string(type);
    EXPECT_EQ(g.missing, "Listen to every sound before answering (2 of 3 heard).") << ms::to_string(type);
    in.heard = {true, true, true};
    EXPECT_TRUE(ms::answer_gate(block(type), in).may_send) << ms::to_string(type);
  }
}

TEST(AnswerGate, OneSoundIsNamedAsTheSound) {
  ms::TrialInputs in;
  in.heard = {false};
  in.complete = true;
  EXPECT_EQ(ms::answer_gate(block(ms::BlockType::identify), in).missing, "Listen to the sound before answering.");
}

TEST(AnswerGate, ListenAllFalseLiftsTheListeningRuleButNotTheAnswer) {
  ms::TrialInputs in;
  in.heard = {false, false};
  in.moved = {false, false};
  in.complete = true;
  EXPECT_TRUE(ms::answer_gate(block(ms::BlockType::ab, false), in).may_send);
  EXPECT_TRUE(ms::answer_gate(block(ms::BlockType::mushra, false), in).may_send);
  in.complete = false;
  const ms::AnswerGate g = ms::answer_gate(block(ms::BlockType::ab, false), in);
  EXPECT_FALSE(g.may_send);
  EXPECT_EQ(g.missing, "Choose an answer.");
}

TEST(AnswerGate, MushraWaitsForEverySliderToBeMoved) {
  ms::TrialInputs in;
  in.heard = {true, true, true, true};
  in.moved = {true, false, false};
  in.complete = true;
  ms::AnswerGate g = ms::answer_gate(block(ms::BlockType::mushra), in);
  EXPECT_FALSE(g.may_send);
  EXPECT_EQ(g.missing, "Rate every sound: move each slider at least once (2 are not rated yet).");
  in.moved = {true, true, false};
  EXPECT_EQ(ms::answer_gate(block(ms::BlockType::mushra), in).missing,
            "Rate every sound: move each slider at least once (1 is not rated yet).");
  in.moved = {true, true, true};
  EXPECT_TRUE(ms::answer_gate(block(ms::BlockType::mushra), in).may_send);
}

TEST(AnswerGate, IncompleteAnswerUsesTheViewsReasonOrTheTypesWording) {
  ms::TrialInputs in;
  in.heard = {true};
  in.complete = false;
  EXPECT_EQ(ms::answer_gate(block(ms::BlockType::magnitude), in).missing, "Type a number.");
  in.why_incomplete = "'abc' is not a number";
  EXPECT_EQ(ms::answer_gate(block(ms::BlockType::magnitude), in).missing, "'abc' is not a number");
}

TEST(AnswerGate, InstructionsAndQuestionnairesHaveNothingToHear) {
  ms::TrialInputs in;
  in.complete = true;
  in.heard = {false};
  EXPECT_TRUE(ms::answer_gate(block(ms::BlockType::instructions), in).may_send);
  EXPECT_TRUE(ms::answer_gate(block(ms::BlockType::questionnaire), in).may_send);
}
