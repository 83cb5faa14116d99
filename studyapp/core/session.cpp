// Session: schedule + results store; see session.hpp.
#include "studyapp/core/session.hpp"

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>

#include "studyapp/core/response_format.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/sha256.hpp"

namespace ms {

namespace {

TrialPosition position_of(const Trial& t) { return {int(t.block), int(t.index)}; }

std::vector<TrialRecord> trial_records(const Schedule& s, const std::map<std::string, std::string>& hashes) {
  std::vector<TrialRecord> out;
  for (const Trial& t : s.trials) {
    TrialRecord r;
    r.block_index = int(t.block);
    r.block_id = t.block_id;
    r.block_type = to_string(t.type);
    r.trial_index = int(t.index);
    r.stimuli = t.stimuli;
    for (const auto& name : t.stimuli) {
      const auto h = hashes.find(name);
      r.stimulus_hashes.push_back(h == hashes.end() ? "" : h->second);
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace

std::int64_t unix_now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

Session::Session(const Protocol& protocol, const std::string& protocol_text, const std::string& participant,
                 const std::string& db_path, const std::map<std::string, std::string>& stimulus_hashes,
                 std::int64_t now_ms)
    : protocol_(protocol), schedule_(make_schedule(protocol, participant)) {
  if (participant.empty()) throw InputError(SourceLocation{protocol.file, 0, 0}, "the participant id is empty");
  store_ = std::make_unique<ResultsStore>(db_path);
  store_->add_study({protocol.study, protocol.title, sha256_hex(protocol_text), protocol_text, protocol.export_personal});
  const auto known = store_->find_participant(protocol.study, participant);
  const std::int64_t pid = known ? *known : store_->add_participant(protocol.study, participant, now_ms);
  if (known) {
    if (const auto open = store_->unfinished_session(pid)) {
      // Same protocol text (checked by add_study) and participant give the same schedule; the stored
      // seed guards against a schedule algorithm that changed between versions.
      if (open->schedule_seed != schedule_.seed)
        throw InputError(SourceLocation{db_path, 0, 0},
                         "session " + std::to_string(open->id) + " of participant '" + participant +
                             "' was scheduled with another seed; start a new database for this version");
      session_ = open->id;
      resumed_ = true;
    }
  }
  if (!resumed_) {
    session_ = store_->start_session(pid, now_ms, schedule_.seed);
    store_->record_trials(session_, trial_records(schedule_, stimulus_hashes));
  }
  // The first trial, in schedule order, without a stored answer.
  std::set<std::pair<int, int>> done;
  for (const auto& p : store_->answered_trials(session_)) done.insert({p.block_index, p.trial_index});
  current_ = 0;
  while (current_ < schedule_.trials.size() &&
         done.count({int(schedule_.trials[current_].block), int(schedule_.trials[current_].index)}))
    ++current_;
  if (finished() && resumed_) store_->finish_session(session_, now_ms);
  if (!finished() && current().type == BlockType::staircase) {
    // Rebuild an interrupted track from its committed steps.
    staircase();
    for (const auto& e : store_->events(session_, position_of(current())))
      if (e.kind == EventKind::step) {
        const auto d = nlohmann::json::parse(e.detail_json);
        track_->record(d.at("correct").get<bool>());
        track_rt_ms_ += d.value("rt_ms", 0.0);
        ++track_plays_;
      }
  }
}

const Trial& Session::current() const {
  if (finished()) throw std::logic_error("Session::current: the session is finished");
  return schedule_.trials[current_];
}

const Block& Session::current_block() const { return protocol_.blocks.at(current().block); }

std::size_t Session::answered() const { return store_->answered_trials(session_).size(); }

void Session::log_event(EventKind kind, const std::string& stimulus, std::int64_t now_ms,
                        const std::string& detail_json) {
  if (finished()) return;
  store_->record_event(session_, {position_of(current()), kind, stimulus, now_ms, detail_json});
}

void Session::answer(const nlohmann::json& value, double rt_ms, int plays, std::int64_t now_ms) {
  const Trial& t = current();
  if (const std::string why = check_answer(current_block(), t, value); !why.empty())
    throw std::invalid_argument("answer to " + t.block_id + " trial " + std::to_string(t.index) + ": " + why);
  store_->record_response(session_, {position_of(t), value.dump(), rt_ms, plays, now_ms});
  at_break_ = t.break_after;
  advance();
  if (finished()) finish(now_ms);
}

StaircaseTrack& Session::staircase() {
  const Block& b = current_block();
  const auto* s = std::get_if<StaircaseBlock>(&b.body);
  if (!s) throw std::logic_error("Session::staircase: the current trial is not a staircase");
  if (!track_) track_.emplace(s->start, s->step, s->down, s->up, s->reversals);
  return *track_;
}

void Session::staircase_step(bool correct, double rt_ms, std::int64_t now_ms) {
  StaircaseTrack& track = staircase();
  const auto* s = std::get_if<StaircaseBlock>(&current_block().body);
  const nlohmann::json detail{{"step", track.levels().size()}, {"level", track.level()}, {"correct", correct},
                              {"rt_ms", rt_ms}};
  store_->record_event(session_, {position_of(current()), EventKind::step, s->stimulus.name, now_ms, detail.dump()});
  track.record(correct);
  track_rt_ms_ += rt_ms;
  ++track_plays_;
  if (!track.finished()) return;
  nlohmann::json value{{"levels", track.levels()}, {"correct", track.answers()}, {"parameter", s->parameter}};
  const auto threshold = track.threshold();
  value["threshold"] = threshold ? nlohmann::json(*threshold) : nlohmann::json(nullptr);
  const double rt = track_rt_ms_;
  const int plays = track_plays_;
  answer(value, rt, plays, now_ms);
}

void Session::advance() {
  track_.reset();
  track_plays_ = 0;
  track_rt_ms_ = 0.0;
  ++current_;
}

void Session::finish(std::int64_t now_ms) { store_->finish_session(session_, now_ms); }

}  // namespace ms
