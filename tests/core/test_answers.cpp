// Typed answers: every answer an earlier version stored reads back and re-encodes to the same text; each
// type's JSON round-trips; the check before storing refuses what does not fit the block, saying why.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "studyapp/core/answers.hpp"
#include "studyapp/core/response_format.hpp"
#include "studyapp/core/results_store.hpp"
#include "support/test_util.hpp"

namespace ms {
namespace {

using nlohmann::json;

TEST(Answers, EveryStoredAnswerOfTheDemoDatabaseReadsBackToTheSameText) {
  test::TempDir dir;
  const std::string db = dir.file("demo.sqlite");
  std::filesystem::copy_file(std::string(MODALSTUDY_SOURCE_DIR) + "/tests/data/answers_v1/demo-autopilot.sqlite", db);
  const ResultsStore store(db, ResultsStore::Mode::read_only);
  const auto rows = store.response_rows();
  ASSERT_EQ(rows.size(), 19u);
  std::set<std::size_t> kinds;
  for (const ResponseRow& r : rows) {
    const Answer a = read_stored_answer(r.block_type, json::parse(r.value_json));
    kinds.insert(a.index());
    EXPECT_EQ(json(a).dump(), r.value_json) << r.block_type;
  }
  EXPECT_EQ(kinds.size(), 10u);  // every block type of the demo, A/B as same/different and as a choice
}

TEST(Answers, EachTypeRoundTripsThroughItsJson) {
  const std::vector<std::pair<std::string, json>> stored{
      {"instructions", "ok"},
      {"ab", "different"},
      {"ab", "B"},
      {"ab", -2},
      {"mushra", json{{"full", 87}, {"lp", 12.5}}},
      {"magnitude", 113.0},
      {"identify", "glass"},
      {"rating", json{{"brightness", 3}}},
      {"adjust", json{{"damping.alpha1", 1.45}}},
      {"staircase", json::parse(R"({"levels":[20.0,19.0],"correct":[false,true],"parameter":"p",)"
                                R"("chosen":["A","B"],"threshold":null})")},
      {"questionnaire", json{{"q1", "fine"}}}};
  for (const auto& [type, j] : stored) EXPECT_EQ(json(read_stored_answer(type, j)), j) << type << " " << j.dump();
  const auto sd = std::get<SameDifferentAnswer>(read_stored_answer("ab", "different"));
  EXPECT_TRUE(sd.different);
  EXPECT_EQ(std::get<ChoiceAnswer>(read_stored_answer("ab", "B")).chosen, AbInterval::b);
  EXPECT_EQ(std::get<BipolarAnswer>(read_stored_answer("ab", -2)).score, -2);
}

TEST(Answers, AStaircaseStoredWithoutChoicesHasNoneAndStaysWithout) {
  const json old = json::parse(R"({"levels":[20.0,19.0],"correct":[0,1],"parameter":"p","threshold":8.5})");
  const auto a = std::get<StaircaseAnswer>(read_stored_answer("staircase", old));
  EXPECT_TRUE(a.chosen.empty());
  EXPECT_EQ(a.correct, (std::vector<bool>{false, true}));
  EXPECT_DOUBLE_EQ(*a.threshold, 8.5);
  EXPECT_FALSE(json(a).contains("chosen"));
  // A choice per step, or none.
  const json short_choices = json::parse(R"({"levels":[20.0,19.0],"correct":[true,true],"chosen":["A"],"threshold":null})");
  EXPECT_THROW(read_stored_answer("staircase", short_choices), AnswerError);
  const json bad_choice = json::parse(R"({"levels":[20.0],"correct":[true],"chosen":["C"],"threshold":null})");
  EXPECT_THROW(read_stored_answer("staircase", bad_choice), AnswerError);
}

Block block_of(BlockType type, BlockBody body) {
  Block b;
  b.type = type;
  b.id = "b";
  b.body = std::move(body);
  return b;
}

TEST(Answers, TheCheckBeforeStoringSaysWhatDoesNotFit) {
  AbBlock sd;
  sd.mode = AbMode::same_different;
  EXPECT_EQ(check_answer(block_of(BlockType::ab, sd), Trial{}, "A"), "expected one of same, different, got \"A\"");
  AbBlock bipolar;
  bipolar.mode = AbMode::bipolar;
  EXPECT_EQ(check_answer(block_of(BlockType::ab, bipolar), Trial{}, 4), "expected an integer from -3 to 3, got 4");
  EXPECT_EQ(check_answer(block_of(BlockType::ab, bipolar), Trial{}, -3), "");
  AbBlock abx;
  abx.mode = AbMode::abx;
  EXPECT_EQ(check_answer(block_of(BlockType::ab, abx), Trial{}, "B"), "");

  Trial mushra_trial;
  mushra_trial.stimuli = {"full", "lp"};
  const Block mushra = block_of(BlockType::mushra, MushraBlock{});
  EXPECT_EQ(check_answer(mushra, mushra_trial, json{{"full", 50}}), "missing 'lp'");
  EXPECT_EQ(check_answer(mushra, mushra_trial, json{{"full", 50}, {"lp", 101}}),
            "'lp' must be a score from 0 to 100, got 101");
  EXPECT_EQ(check_answer(mushra, mushra_trial, json{{"full", 50}, {"lp", 0}, {"x", 1}}), "unexpected key 'x'");
  EXPECT_EQ(check_answer(mushra, mushra_trial, json{{"full", 50}, {"lp", 0.5}}), "");

  RatingBlock rating;
  rating.attributes = {RatingAttribute{"bright", 5, "dull", "bright"}};
  EXPECT_EQ(check_answer(block_of(BlockType::rating, rating), Trial{}, json{{"bright", 6}}),
            "'bright' must be an integer from 1 to the attribute's points, got 6");
  EXPECT_EQ(check_answer(block_of(BlockType::rating, rating), Trial{}, json{{"bright", 5}}), "");

  AdjustBlock adjust;
  adjust.sliders = {Slider{"damping.alpha1", 10.0, 0.5}};
  EXPECT_EQ(check_answer(block_of(BlockType::adjust, adjust), Trial{}, json{{"damping.alpha1", 10.0}}), "");
  EXPECT_NE(check_answer(block_of(BlockType::adjust, adjust), Trial{}, json{{"damping.alpha1", 10.5}}), "");

  QuestionnaireBlock q;
  q.questions = {Question{"", "Comments?", {}}, Question{"hp", "Headphones?", {"open", "closed"}}};
  const Block questionnaire = block_of(BlockType::questionnaire, q);
  EXPECT_EQ(check_answer(questionnaire, Trial{}, json{{"q1", ""}, {"hp", "open"}}), "");
  EXPECT_EQ(check_answer(questionnaire, Trial{}, json{{"q1", ""}, {"hp", "none"}}),
            "'hp' must be text (or one of the question's options), got \"none\"");

  IdentifyBlock identify;
  identify.labels = {"metal", "glass"};
  EXPECT_EQ(std::get<IdentifyAnswer>(read_answer(block_of(BlockType::identify, identify), Trial{}, "glass")).label,
            "glass");
  EXPECT_EQ(check_answer(block_of(BlockType::identify, identify), Trial{}, "wood"),
            "expected one of metal, glass, got \"wood\"");
  EXPECT_EQ(check_answer(block_of(BlockType::instructions, InstructionsBlock{}), Trial{}, "yes"),
            "instructions are answered with \"ok\"");
}

TEST(Answers, AnAbChoiceNamesItsStimulus) {
  const json stimuli{"glass", "metal", "metal"};
  EXPECT_EQ(ab_chosen_stimulus(stimuli, AbInterval::a), "glass");
  EXPECT_TRUE(abx_correct(stimuli, AbInterval::b));
  EXPECT_FALSE(abx_correct(stimuli, "A"));
  EXPECT_EQ(to_string(other(AbInterval::a)), "B");
}

}  // namespace
}  // namespace ms
