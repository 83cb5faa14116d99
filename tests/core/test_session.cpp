// Session: answers are checked, committed and advance the schedule; reopening resumes at the first
// unanswered trial with the same schedule; staircase tracks resume from their committed steps.
#include <gtest/gtest.h>

#include "core_fixtures.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "synthesis/input_error.hpp"

namespace ms {
namespace {

using testing::good_answer;
using testing::SmallStudy;

TEST(Session, AnswersAreCheckedCommittedAndAdvance) {
  test::TempDir dir;
  SmallStudy study(dir);
  Session s = study.open("P01", dir.file("r.sqlite"), 1000);
  EXPECT_FALSE(s.resumed());
  ASSERT_EQ(s.total(), 6u);  // instructions + identify 2 stimuli x 2 repeats + one MUSHRA screen
  EXPECT_EQ(s.current().type, BlockType::instructions);
  // A malformed answer is refused and nothing is stored.
  EXPECT_THROW(s.answer("yes", 10.0, 0, 1001), std::invalid_argument);
  EXPECT_EQ(s.answered(), 0u);
  s.answer("ok", 10.0, 0, 1001);
  ASSERT_EQ(s.current().type, BlockType::identify);
  EXPECT_THROW(s.answer("metal", 10.0, 1, 1002), std::invalid_argument);  // not a label
  while (!s.finished()) {
    if (s.current().type == BlockType::mushra) {
      nlohmann::json missing = good_answer(s);
      missing.erase(s.current().stimuli.back());
      EXPECT_THROW(s.answer(missing, 1.0, 1, 1003), std::invalid_argument);  // every condition rated
    }
    s.log_event(EventKind::play, s.current().stimuli.empty() ? "" : s.current().stimuli[0], 1004);
    s.answer(good_answer(s), 500.0, 1, 1005);
  }
  EXPECT_EQ(s.answered(), 6u);
  EXPECT_EQ(s.store().count("responses"), 6);
  for (const auto& e : s.store().event_rows()) EXPECT_TRUE(e.detail_json.empty()) << e.detail_json;
  EXPECT_EQ(s.store().count("events"), 5);  // instructions has no stimulus but its event still counts
  const auto summaries = s.store().session_summaries();
  ASSERT_EQ(summaries.size(), 1u);
  ASSERT_TRUE(summaries[0].finished_ms.has_value());  // the last answer finishes the session
  // Recipe hashes are stored with the trials (mushra trial: reference, lowq, lp).
  for (const auto& row : s.store().trial_rows()) {
    if (row.block_type == "mushra") {
      EXPECT_NE(row.hashes_json.find(study.cache.hash("lp")), std::string::npos);
    }
  }
}

TEST(Session, EventsCarryTheVariantPlayed) {
  test::TempDir dir;
  SmallStudy study(dir);
  Session s = study.open("P05", dir.file("r.sqlite"), 1000);
  s.answer("ok", 1.0, 0, 1001);
  const std::string detail = R"({"hash":"abc","set":{"amp_scale":0.7}})";
  s.log_event(EventKind::play, s.current().stimuli[0], 1002, detail);
  const auto rows = s.store().event_rows();
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].detail_json, detail);
  EXPECT_EQ(rows[0].kind, "play");
  EXPECT_EQ(rows[0].stimulus_hash, study.cache.hash(s.current().stimuli[0]));
}

TEST(Session, ReopeningResumesAtTheFirstUnansweredTrialWithTheSameSchedule) {
  test::TempDir dir;
  SmallStudy study(dir);
  std::vector<std::vector<std::string>> first_order;
  {
    Session s = study.open("P02", dir.file("r.sqlite"), 1000);
    for (const auto& t : s.schedule().trials) first_order.push_back(t.stimuli);
    for (int i = 0; i < 3; ++i) s.answer(good_answer(s), 100.0, 1, 1000 + i);
  }  // the program "stops" here
  Session again = study.open("P02", dir.file("r.sqlite"), 5000);
  EXPECT_TRUE(again.resumed());
  EXPECT_EQ(again.current_index(), 3u);
  EXPECT_EQ(again.answered(), 3u);
  std::vector<std::vector<std::string>> order;
  for (const auto& t : again.schedule().trials) order.push_back(t.stimuli);
  EXPECT_EQ(order, first_order);
  while (!again.finished()) again.answer(good_answer(again), 100.0, 1, 6000);
  EXPECT_EQ(again.store().count("responses"), 6);
  EXPECT_EQ(again.store().count("sessions"), 1);
  // A finished participant is refused; a second visit is asked for explicitly.
  EXPECT_THROW(study.open("P02", dir.file("r.sqlite"), 9000), ParticipantFinished);
  Session next = study.open("P02", dir.file("r.sqlite"), 9000, SessionStart{true, false});
  EXPECT_FALSE(next.resumed());
  EXPECT_EQ(next.current_index(), 0u);
}

TEST(Session, AChangedProtocolIsRefusedForTheSameDatabase) {
  test::TempDir dir;
  SmallStudy study(dir);
  { Session s = study.open("P03", dir.file("r.sqlite"), 1000); }
  try {
    Session s(study.protocol, study.text + "# edited\n", "P03", dir.file("r.sqlite"), study.cache.hashes(), 1000);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different protocol"), std::string::npos) << e.what();
  }
}

// The interval that scores as `correct` in the session's current staircase step.
AbInterval choice_scoring(Session& s, bool correct) {
  return correct ? other(s.staircase_comparison()) : s.staircase_comparison();
}

TEST(Session, StaircaseStepsAreCommittedAndATrackResumes) {
  test::TempDir dir;
  SmallStudy study(dir, "  - {type: staircase, id: sc, stimulus: low, reference: high, parameter: amp_scale, start: 0.2,\n"
                        "     step: 0.05, down_up: [2, 1], reversals: 4}\n");
  const bool pattern[] = {true, true, false, true, true, false, true, true, false, false, true, true, true, true};
  std::size_t used = 0;
  {
    Session s = study.open("P04", dir.file("r.sqlite"), 1000);
    while (s.current().type != BlockType::staircase) s.answer(good_answer(s), 1.0, 1, 1000);
    for (; used < 5; ++used) s.staircase_step(choice_scoring(s, pattern[used]), 300.0, 2000);
    EXPECT_EQ(s.staircase().levels().size(), 5u);
  }
  Session s = study.open("P04", dir.file("r.sqlite"), 3000);
  ASSERT_TRUE(s.resumed());
  ASSERT_EQ(s.current().type, BlockType::staircase);
  EXPECT_EQ(s.staircase().levels().size(), 5u);  // rebuilt from the committed steps
  StaircaseTrack replay(0.2, 0.05, 2, 1, 4);
  for (std::size_t i = 0; i < 5; ++i) replay.record(pattern[i]);
  EXPECT_DOUBLE_EQ(s.staircase().level(), replay.level());
  while (!s.finished()) s.staircase_step(choice_scoring(s, pattern[used++ % 14]), 300.0, 4000);
  const auto r = s.store().response(s.id(), {3, 0});
  ASSERT_TRUE(r.has_value());
  const auto v = nlohmann::json::parse(r->value_json);
  EXPECT_EQ(v["parameter"], "amp_scale");
  EXPECT_EQ(v["levels"].size(), used);
  EXPECT_EQ(r->plays, int(used));
  EXPECT_FALSE(v["threshold"].is_null());
}

}  // namespace
}  // namespace ms
