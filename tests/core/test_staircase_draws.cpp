// The staircase's draw of which interval holds the comparison and the scoring of the listener's choice
// are core's: the same seed and position draw the same interval, a resumed track draws the rest as an
// uninterrupted one would, and the stored answer and the export keep the interval chosen.
#include <gtest/gtest.h>

#include "core_fixtures.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/core/staircase_track.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "studyapp/core/tidy_tables.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {
namespace {

std::string write_staircase_study(const test::TempDir& dir) {
  testing::write_small_study(dir);  // the parameter sets
  return dir.write("stair.yaml",
                   "study: stair\ntitle: Stair\nsample_rate: 44100\nseed: 7\n"
                   "stimuli:\n  low: {paramset: sets/low.yaml}\n  high: {paramset: sets/high.yaml}\n"
                   "blocks:\n"
                   "  - {type: staircase, id: sc, stimulus: low, reference: high, parameter: amp_scale, start: 0.2,\n"
                   "     step: 0.05, down_up: [2, 1], reversals: 4}\n");
}

// The listener's choice at a step: not tied to where the comparison is.
AbInterval choice_at(std::size_t step) { return step % 3 == 0 ? AbInterval::b : AbInterval::a; }

// Answers up to `steps` steps of the current track (all when 0); appends the draw of each step.
void run_steps(Session& s, std::vector<AbInterval>& draws, std::size_t steps = 0) {
  for (std::size_t n = 0; !s.finished() && (steps == 0 || n < steps); ++n) {
    const std::size_t step = s.staircase().levels().size();
    draws.push_back(s.staircase_comparison());
    const bool correct = s.staircase_step(choice_at(step), 300.0, 2000);
    EXPECT_EQ(correct, draws.back() != choice_at(step)) << "step " << step;
  }
}

struct Fixture {
  test::TempDir dir;
  std::string path = write_staircase_study(dir);
  Protocol protocol = load_protocol(path);
  StimulusCache cache{protocol, ""};

  std::unique_ptr<Session> open(const std::string& participant, const std::string& db) {
    return std::make_unique<Session>(protocol, testing::file_text(path), participant, dir.file(db), cache.hashes(), 1000);
  }
};

TEST(StaircaseDraws, TheSameSeedAndPositionDrawTheSameInterval) {
  std::size_t in_b = 0, differ_seed = 0, differ_block = 0, differ_trial = 0;
  for (std::size_t step = 0; step < 400; ++step) {
    const AbInterval i = staircase_comparison(42, "sc", 0, step);
    EXPECT_EQ(staircase_comparison(42, "sc", 0, step), i);
    in_b += i == AbInterval::b ? 1 : 0;
    differ_seed += staircase_comparison(43, "sc", 0, step) != i ? 1 : 0;
    differ_block += staircase_comparison(42, "sc2", 0, step) != i ? 1 : 0;
    differ_trial += staircase_comparison(42, "sc", 1, step) != i ? 1 : 0;
  }
  // A fair coin: 400 draws put B in 200 +- 4 standard deviations (10 each).
  EXPECT_GT(in_b, 160u);
  EXPECT_LT(in_b, 240u);
  // Another seed, block or track draws independently: about half the draws differ.
  for (std::size_t d : {differ_seed, differ_block, differ_trial}) {
    EXPECT_GT(d, 160u);
    EXPECT_LT(d, 240u);
  }
}

TEST(StaircaseDraws, TheListenerNamesTheReferenceIntervalToBeRight) {
  EXPECT_TRUE(staircase_correct(AbInterval::a, AbInterval::b));
  EXPECT_TRUE(staircase_correct(AbInterval::b, AbInterval::a));
  EXPECT_FALSE(staircase_correct(AbInterval::a, AbInterval::a));
  EXPECT_FALSE(staircase_correct(AbInterval::b, AbInterval::b));
}

TEST(StaircaseDraws, TheSameParticipantDrawsTheSameAndAnotherDrawsOtherwise) {
  Fixture f;
  std::vector<AbInterval> first, again, other_participant;
  run_steps(*f.open("P1", "a.sqlite"), first);
  run_steps(*f.open("P1", "b.sqlite"), again);
  run_steps(*f.open("P2", "c.sqlite"), other_participant, first.size());
  ASSERT_GT(first.size(), 6u);
  EXPECT_EQ(first, again);
  EXPECT_NE(first, other_participant);
}

TEST(StaircaseDraws, AResumedTrackDrawsTheRestAsAnUninterruptedOneAndKeepsTheChoices) {
  Fixture f;
  std::vector<AbInterval> whole, resumed;
  run_steps(*f.open("P1", "whole.sqlite"), whole);
  {
    auto s = f.open("P1", "resumed.sqlite");
    run_steps(*s, resumed, 5);
    ASSERT_FALSE(s->finished());
  }
  {
    auto s = f.open("P1", "resumed.sqlite");
    ASSERT_TRUE(s->resumed());
    EXPECT_EQ(s->staircase().levels().size(), 5u);
    run_steps(*s, resumed);
    ASSERT_TRUE(s->finished());
    // The stored track: the interval chosen at every step, and correct where it was not the comparison.
    const auto r = s->store().response(s->id(), {0, 0});
    ASSERT_TRUE(r.has_value());
    const auto track = std::get<StaircaseAnswer>(read_stored_answer("staircase", nlohmann::json::parse(r->value_json)));
    ASSERT_EQ(track.chosen.size(), resumed.size());
    for (std::size_t i = 0; i < resumed.size(); ++i) {
      EXPECT_EQ(track.chosen[i], choice_at(i)) << i;
      EXPECT_EQ(track.correct[i], resumed[i] != choice_at(i)) << i;
    }
  }
  EXPECT_EQ(resumed, whole);

  // The export: one row per step with the interval chosen beside `correct`.
  export_results(f.dir.file("resumed.sqlite"), f.dir.file("out"));
  const TidyCsv t = TidyCsv::read(f.dir.file("out/staircase.csv"));
  ASSERT_EQ(t.rows(), resumed.size());
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const std::size_t step = static_cast<std::size_t>(t.number(i, t.column("step")));
    EXPECT_EQ(t.cell(i, t.column("chosen")), to_string(choice_at(step))) << i;
    EXPECT_EQ(t.cell(i, t.column("correct")), resumed[step] != choice_at(step) ? "1" : "0") << i;
  }
  // Each committed step says where the comparison was and what was chosen.
  ResultsStore store(f.dir.file("resumed.sqlite"), ResultsStore::Mode::read_only);
  std::size_t steps = 0;
  for (const EventRow& e : store.event_rows()) {
    if (e.kind != "step") continue;
    const auto d = nlohmann::json::parse(e.detail_json);
    EXPECT_EQ(d.at("comparison"), to_string(resumed.at(steps)));
    EXPECT_EQ(d.at("chosen"), to_string(choice_at(steps)));
    ++steps;
  }
  EXPECT_EQ(steps, resumed.size());
}

// A store with tracks from before choices were kept and after: the column is there, NA for the old steps.
TEST(StaircaseDraws, OldTracksBesideNewOnesExportNaAsTheirChoice) {
  ResponseRow old_track;
  old_track.study = "s";
  old_track.participant = 1;
  old_track.session = 1;
  old_track.block_id = "sc";
  old_track.block_type = "staircase";
  old_track.stimuli_json = R"(["low"])";
  old_track.value_json = R"({"levels":[0.2,0.15],"correct":[true,false],"parameter":"amp_scale","threshold":null})";
  ResponseRow new_track = old_track;
  new_track.session = 2;
  new_track.value_json =
      R"({"levels":[0.2],"correct":[true],"chosen":["B"],"parameter":"amp_scale","threshold":null})";
  const TidyCsv t = TidyCsv::parse(tidy_tables({old_track, new_track}).at("staircase.csv"), "staircase.csv");
  ASSERT_EQ(t.rows(), 3u);
  EXPECT_EQ(t.cell(0, t.column("chosen")), "NA");
  EXPECT_EQ(t.cell(1, t.column("chosen")), "NA");
  EXPECT_EQ(t.cell(2, t.column("chosen")), "B");
  EXPECT_EQ(t.cell(2, t.column("correct")), "1");
  // Only old tracks: the table keeps the columns it always had.
  const std::string only_old = tidy_tables({old_track}).at("staircase.csv");
  EXPECT_EQ(only_old.substr(0, only_old.find('\r')),
            "study,participant,session,autopilot,block,trial,stimulus,parameter,step,level,next_level,correct,threshold");
}

}  // namespace
}  // namespace ms
