// Session: schedule + results store; see session.hpp.
#include "studyapp/core/session.hpp"

#include <algorithm>
#include <chrono>
#include <set>
#include <stdexcept>

#include "studyapp/core/lease_keeper.hpp"
#include "studyapp/core/participant_id.hpp"
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
                 std::int64_t now_ms, const SessionStart& start)
    : protocol_(protocol),
      participant_(normalize_participant_id(participant)),
      schedule_(make_schedule(protocol, participant_)) {
  store_ = std::make_unique<ResultsStore>(db_path);
  for (const auto& other : look_alike_ids(participant_, store_->participant_codes(protocol.study)))
    warnings_.push_back("participant id '" + participant_ + "' differs only by case or spaces from '" + other +
                        "', who is already in this database: check it is not a typo");
  SessionRequest request;
  request.study_id = protocol.study;
  request.participant = participant_;
  request.now_ms = now_ms;
  request.schedule_seed = schedule_.seed;
  request.trials = trial_records(schedule_, stimulus_hashes);
  request.new_session = start.new_session;
  request.autopilot = start.autopilot;
  request.holder = this_process();
  const OpenedSession opened = store_->open_session(
      {protocol.study, protocol.title, sha256_hex(protocol_text), protocol_text, protocol.export_personal}, request);
  session_ = opened.session;
  resumed_ = opened.resumed;
  lease_keeper_ = LeaseKeeper::of(db_path);
  lease_keeper_->keep(session_);
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
    bool all_chosen = true;
    for (const auto& e : store_->events(session_, position_of(current())))
      if (e.kind == EventKind::step) {
        const auto d = nlohmann::json::parse(e.detail_json);
        track_->record(d.at("correct").get<bool>());
        if (d.contains("chosen")) track_chosen_.push_back(d["chosen"].get<ChoiceAnswer>().chosen);
        else all_chosen = false;  // a step stored before choices were kept
        track_rt_ms_ += d.value("rt_ms", 0.0);
        ++track_plays_;
      }
    if (!all_chosen) track_chosen_.clear();
  }
  if (!finished() && (current().type == BlockType::limits || current().type == BlockType::tokens)) {
    // An interrupted series continues after its committed steps.
    const bool limits_trial = current().type == BlockType::limits;
    if (limits_trial) limits();
    else tokens();
    for (const auto& e : store_->events(session_, position_of(current())))
      if (e.kind == EventKind::step) {
        const auto d = nlohmann::json::parse(e.detail_json);
        const bool different = d.at("response").get<SameDifferentAnswer>().different;
        if (limits_trial) series_->record(different);
        else token_series_->record(different);
        track_rt_ms_ += d.value("rt_ms", 0.0);
        ++track_plays_;
      }
  }
}

Session::~Session() {
  lease_keeper_->drop(session_);
  try {
    store_->release_lease(session_, this_process());
  } catch (const std::exception&) {  // a lease left behind is stale once this process is gone
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

AbInterval Session::staircase_comparison() {
  const std::size_t step = staircase().levels().size();
  return ms::staircase_comparison(schedule_.seed, current().block_id, current().index, step);
}

bool Session::staircase_step(AbInterval chosen, double rt_ms, std::int64_t now_ms) {
  StaircaseTrack& track = staircase();
  const auto* s = std::get_if<StaircaseBlock>(&current_block().body);
  const AbInterval comparison = staircase_comparison();
  const bool correct = staircase_correct(comparison, chosen);
  const nlohmann::json detail{{"step", track.levels().size()}, {"level", track.level()},
                              {"comparison", to_string(comparison)}, {"chosen", to_string(chosen)},
                              {"correct", correct}, {"rt_ms", rt_ms}};
  store_->record_event(session_, {position_of(current()), EventKind::step, s->stimulus.name, now_ms, detail.dump()});
  const bool known_choices = track_chosen_.size() == track.levels().size();
  track.record(correct);
  if (known_choices) track_chosen_.push_back(chosen);
  track_rt_ms_ += rt_ms;
  ++track_plays_;
  if (!track.finished()) return correct;
  StaircaseAnswer value{s->parameter, track.levels(), track.answers(), track_chosen_, track.threshold()};
  const double rt = track_rt_ms_;
  const int plays = track_plays_;
  answer(value, rt, plays, now_ms);
  return correct;
}

DescendingSeries& Session::limits() {
  const auto* l = std::get_if<LimitsBlock>(&current_block().body);
  if (!l) throw std::logic_error("Session::limits: the current trial is not a method-of-limits series");
  if (!series_) series_.emplace(l->start, l->step, l->floor);
  return *series_;
}

bool Session::limits_step(bool different, double rt_ms, std::int64_t now_ms) {
  DescendingSeries& series = limits();
  const auto* l = std::get_if<LimitsBlock>(&current_block().body);
  const nlohmann::json detail{{"step", series.levels().size()}, {"level", series.level()},
                              {"response", SameDifferentAnswer{different}}, {"rt_ms", rt_ms}};
  store_->record_event(session_, {position_of(current()), EventKind::step, l->stimulus.name, now_ms, detail.dump()});
  series.record(different);
  track_rt_ms_ += rt_ms;
  ++track_plays_;
  if (!series.finished()) return true;
  const LimitsAnswer value{l->parameter, series.levels(), series.different(), series.threshold()};
  const double rt = track_rt_ms_;
  const int plays = track_plays_;
  answer(value, rt, plays, now_ms);
  return false;
}

TokenSeries& Session::tokens() {
  const auto* t = std::get_if<TokensBlock>(&current_block().body);
  if (!t) throw std::logic_error("Session::tokens: the current trial is not a token series");
  if (!token_series_) token_series_.emplace(t->from, t->to);
  return *token_series_;
}

bool Session::tokens_step(bool different, double rt_ms, std::int64_t now_ms) {
  TokenSeries& series = tokens();
  const auto* t = std::get_if<TokensBlock>(&current_block().body);
  const nlohmann::json detail{{"step", series.different().size()}, {"reference", series.reference()},
                              {"comparison", series.comparison()}, {"response", SameDifferentAnswer{different}},
                              {"rt_ms", rt_ms}};
  store_->record_event(session_, {position_of(current()), EventKind::step, t->stimulus.name, now_ms, detail.dump()});
  series.record(different);
  track_rt_ms_ += rt_ms;
  ++track_plays_;
  if (!series.finished()) return true;
  const TokensAnswer value{series.from(), series.to(), series.different()};
  const double rt = track_rt_ms_;
  const int plays = track_plays_;
  answer(value, rt, plays, now_ms);
  return false;
}

void Session::advance() {
  track_.reset();
  series_.reset();
  token_series_.reset();
  track_chosen_.clear();
  track_plays_ = 0;
  track_rt_ms_ = 0.0;
  ++current_;
}

void Session::finish(std::int64_t now_ms) { store_->finish_session(session_, now_ms); }

}  // namespace ms
