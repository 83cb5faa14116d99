// A participant's session: the protocol's schedule walked trial by trial. Every answer is committed to
// the results store before the session moves on; opening the same study + participant + database
// again resumes the unfinished session at its first unanswered trial with the same schedule.
// Staircase trials run their track inside the trial: core draws which interval holds the comparison
// and scores the listener's choice; each step is committed as a "step" event, so a track interrupted
// by a crash continues where it stopped, with the same draws. Method-of-limits trials run one descending
// series inside the trial the same way (each "same"/"different" a "step" event), and token trials one adaptive
// token series (each comparison a "step" event). While a Session object lives it holds the
// session's lease (the process's LeaseKeeper renews it), so no other process can answer for the participant.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studyapp/core/protocol.hpp"
#include "studyapp/core/results_store.hpp"
#include "studyapp/core/schedule.hpp"
#include "analysis/stats/token_series.hpp"
#include "studyapp/core/descending_series.hpp"
#include "studyapp/core/staircase_track.hpp"

namespace ms {

class LeaseKeeper;

struct SessionStart {
  bool new_session = false;  // run a participant who finished the study once more (a new session)
  bool autopilot = false;    // the simulated listener answers (marked in the store and the export)
};

class Session {
 public:
  // `stimulus_hashes` (name -> hash, see StimulusCache) are stored with each scheduled trial. The
  // participant id is normalised (participant_id.hpp). Throws InputError if the database belongs to
  // a different version of the same study (protocol hash differs) or is not a ModalStudy database,
  // ParticipantFinished if the participant finished and !start.new_session, SessionInUse if another
  // live process runs the participant's session.
  Session(const Protocol& protocol, const std::string& protocol_text, const std::string& participant,
          const std::string& db_path, const std::map<std::string, std::string>& stimulus_hashes,
          std::int64_t now_ms, const SessionStart& start = {});
  ~Session();  // releases the lease
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  const std::string& participant() const { return participant_; }  // as normalised
  // Things the person starting the session should read, e.g. an id that looks like another one.
  const std::vector<std::string>& warnings() const { return warnings_; }

  const Protocol& protocol() const { return protocol_; }
  const Schedule& schedule() const { return schedule_; }
  std::int64_t id() const { return session_; }
  bool resumed() const { return resumed_; }  // an unfinished session was continued
  ResultsStore& store() { return *store_; }

  bool finished() const { return current_ >= schedule_.trials.size(); }
  std::size_t current_index() const { return current_; }   // into schedule().trials
  const Trial& current() const;                            // precondition: !finished()
  const Block& current_block() const;
  std::size_t answered() const;                            // trials answered so far
  std::size_t total() const { return schedule_.trials.size(); }
  // True right after answering a trial that ends a stretch of `break_after` trials.
  bool at_break() const { return at_break_; }

  // Commits a play/stop/switch event of the current trial; `detail_json` describes a variant played
  // (e.g. an adjust trial's slider values and recipe hash), "" for none.
  void log_event(EventKind kind, const std::string& stimulus, std::int64_t now_ms, const std::string& detail_json = "");

  // Checks the answer (see response_format.hpp), commits it, then advances. Throws
  // std::invalid_argument naming the problem if the answer does not fit the trial (nothing stored).
  void answer(const nlohmann::json& value, double rt_ms, int plays, std::int64_t now_ms);

  // Staircase trials: the live track of the current trial (rebuilt from stored steps on resume).
  StaircaseTrack& staircase();
  // Which interval holds the comparison in the step about to be answered (staircase_comparison of the
  // schedule's seed and the trial's position: the same after a resume).
  AbInterval staircase_comparison();
  // Scores the interval the listener chose, commits the step (level, comparison, choice, correct) and,
  // when the track finishes, answers the trial with the whole track and advances. Returns whether the
  // choice was right.
  bool staircase_step(AbInterval chosen, double rt_ms, std::int64_t now_ms);

  // Method-of-limits trials: the live series of the current trial (rebuilt from stored steps on resume).
  DescendingSeries& limits();
  // Commits the answer at the series' level as a step and, when the series ends (the first
  // "different", the floor), answers the trial with the whole series and advances. Returns whether
  // the series goes on in this trial.
  bool limits_step(bool different, double rt_ms, std::int64_t now_ms);

  // Token trials: the live series of the current trial (rebuilt from stored steps on resume); its
  // reference() and comparison() are the two tokens (prune.keep) the next step plays.
  TokenSeries& tokens();
  // Commits the answer to the comparison as a step and, after the last token, answers the trial with
  // the whole series and advances. Returns whether the series goes on in this trial.
  bool tokens_step(bool different, double rt_ms, std::int64_t now_ms);

  // Marks the session finished in the store (done automatically after the last answer).
  void finish(std::int64_t now_ms);

 private:
  void advance();

  const Protocol& protocol_;
  std::string participant_;
  Schedule schedule_;
  std::unique_ptr<ResultsStore> store_;
  std::int64_t session_ = 0;
  bool resumed_ = false;
  std::size_t current_ = 0;
  bool at_break_ = false;
  std::optional<StaircaseTrack> track_;
  std::optional<DescendingSeries> series_;
  std::optional<TokenSeries> token_series_;
  std::vector<AbInterval> track_chosen_;  // per step; empty when a resumed track's early steps lack it
  int track_plays_ = 0;
  double track_rt_ms_ = 0.0;
  std::vector<std::string> warnings_;
  std::shared_ptr<LeaseKeeper> lease_keeper_;  // renews the lease while the session is open
};

// Milliseconds since the Unix epoch (system clock).
std::int64_t unix_now_ms();

}  // namespace ms
