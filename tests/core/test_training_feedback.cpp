// training_feedback: right/wrong from the trial's stimuli (same/different, ABX), the truth labels
// (identify) and the hidden reference's rating (MUSHRA); none for types without a right answer.
#include <gtest/gtest.h>

#include "studyapp/core/training_feedback.hpp"

namespace {

ms::Block ab_block(ms::AbMode mode) {
  ms::Block b;
  b.type = ms::BlockType::ab;
  ms::AbBlock body;
  body.mode = mode;
  b.body = body;
  return b;
}

ms::Trial trial(std::vector<std::string> stimuli, std::string reference = "") {
  ms::Trial t;
  t.stimuli = std::move(stimuli);
  t.reference = std::move(reference);
  return t;
}

}  // namespace

TEST(TrainingFeedback, SameDifferentFromTheNamesOfAAndB) {
  const ms::Protocol p;
  const ms::Block b = ab_block(ms::AbMode::same_different);
  auto f = ms::training_feedback(p, b, trial({"metal", "glass"}), "different");
  ASSERT_TRUE(f.has_value());
  EXPECT_TRUE(f->correct);
  EXPECT_EQ(f->message, "Right: A and B were different sounds.");
  f = ms::training_feedback(p, b, trial({"metal", "metal"}), "different");
  EXPECT_FALSE(f->correct);
  EXPECT_EQ(f->message, "Not quite: A and B were the same sound.");
}

TEST(TrainingFeedback, AbxSaysWhichOneXWas) {
  const ms::Protocol p;
  const ms::Block b = ab_block(ms::AbMode::abx);
  EXPECT_TRUE(ms::training_feedback(p, b, trial({"full", "plate", "plate"}), "B")->correct);
  const auto f = ms::training_feedback(p, b, trial({"full", "plate", "full"}), "B");
  EXPECT_FALSE(f->correct);
  EXPECT_EQ(f->message, "Not quite: X was A.");
}

TEST(TrainingFeedback, NoRightAnswerForPreferenceAndBipolar) {
  const ms::Protocol p;
  EXPECT_FALSE(ms::training_feedback(p, ab_block(ms::AbMode::preference), trial({"a", "b"}), "A").has_value());
  EXPECT_FALSE(ms::training_feedback(p, ab_block(ms::AbMode::bipolar), trial({"a", "b"}), 2).has_value());
}

TEST(TrainingFeedback, IdentifyUsesTruthThenTheStimulusName) {
  ms::Protocol p;
  ms::StimulusSource s;
  s.name = "emg-disc-metal";
  s.truth = {{"material", "metal"}};
  p.stimuli.push_back(s);
  ms::Block b;
  b.type = ms::BlockType::identify;
  b.body = ms::IdentifyBlock{{}, {"metal", "glass", "wood"}};
  auto f = ms::training_feedback(p, b, trial({"emg-disc-metal"}), "glass");
  ASSERT_TRUE(f.has_value());
  EXPECT_FALSE(f->correct);
  EXPECT_EQ(f->message, "Not quite: the sound was metal.");
  EXPECT_TRUE(ms::training_feedback(p, b, trial({"wood"}), "wood")->correct);
  EXPECT_FALSE(ms::training_feedback(p, b, trial({"unlabelled"}), "wood").has_value());
}

TEST(TrainingFeedback, MushraHiddenReferenceAtLeast90) {
  const ms::Protocol p;
  ms::Block b;
  b.type = ms::BlockType::mushra;
  b.body = ms::MushraBlock{};
  const ms::Trial t = trial({"lp35", "full", "plate"}, "full");
  auto f = ms::training_feedback(p, b, t, {{"lp35", 20}, {"full", 70}, {"plate", 80}});
  ASSERT_TRUE(f.has_value());
  EXPECT_FALSE(f->correct);
  EXPECT_EQ(f->message, "Not quite: sound B was the reference itself (hidden); it should be rated 90 or more.");
  EXPECT_TRUE(ms::training_feedback(p, b, t, {{"lp35", 20}, {"full", 95}, {"plate", 80}})->correct);
}

TEST(TrainingFeedback, MushraLettersGoOnAfterZ) {
  EXPECT_EQ(ms::mushra_letter(0), "A");
  EXPECT_EQ(ms::mushra_letter(11), "L");
  EXPECT_EQ(ms::mushra_letter(25), "Z");
  EXPECT_EQ(ms::mushra_letter(26), "AA");
}
