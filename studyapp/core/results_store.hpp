// ResultsStore: a study's participants, sessions, trials, responses and playback events, in one SQLite
// file (sqlite_store.hpp, the embedded default) or one PostgreSQL database shared by many booths and
// servers (postgres_store.hpp), chosen by the location (store_location.hpp); both behave the same.
// Every response is durable (committed, on disk) before record_response returns. A store is checked
// on every open (a damaged or foreign one is refused by name and never written to), and each running
// session is leased to one process (see session_lease.hpp), the lease checked inside the database.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "studyapp/core/session_lease.hpp"
#include "studyapp/core/store_connection.hpp"
#include "studyapp/core/store_error.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

struct StudyRecord {
  std::string id;  // the protocol's `study:` id
  std::string title;
  std::string protocol_sha256;
  std::string protocol_text;
  bool export_personal = false;  // may participant codes leave the database on export?
};

// One scheduled trial, as shown to the participant.
struct TrialRecord {
  int block_index = 0;
  std::string block_id;
  std::string block_type;  // ab, mushra, identify, ...
  int trial_index = 0;
  std::vector<std::string> stimuli;          // stimulus names in presentation order
  std::vector<std::string> stimulus_hashes;  // recipe hashes, same order
};

struct TrialPosition {
  int block_index = 0;
  int trial_index = 0;
  friend bool operator==(const TrialPosition&, const TrialPosition&) = default;
};

struct ResponseRecord {
  TrialPosition trial;
  std::string value_json;  // the answer as JSON text: "metal", 73, {"ref":100,"e16":80}
  double rt_ms = 0.0;
  int plays = 0;
  std::int64_t timestamp_ms = 0;  // Unix time in milliseconds
};

// play/stop/switch: playback; step: one answered step of a staircase track (detail holds it).
enum class EventKind { play, stop, switch_to, step };
std::string to_string(EventKind kind);  // "play", "stop", "switch", "step"

struct PlaybackEvent {
  TrialPosition trial;
  EventKind kind = EventKind::play;
  std::string stimulus;
  std::int64_t timestamp_ms = 0;
  std::string detail_json;  // "" = none; e.g. {"level":18,"correct":true} or slider overrides
};

struct SessionRecord {
  std::int64_t id = 0, participant = 0, started_ms = 0;
  std::optional<std::int64_t> finished_ms;
  std::uint64_t schedule_seed = 0;
  bool autopilot = false;  // answered (at least in part) by the simulated listener
};

// What a program asks for when it opens a participant's session (ResultsStore::open_session).
struct SessionRequest {
  std::string study_id, participant;  // participant already normalised (participant_id.hpp)
  std::int64_t now_ms = 0;
  std::uint64_t schedule_seed = 0;
  std::vector<TrialRecord> trials;  // the schedule, stored when a new session starts
  bool new_session = false;         // start another session for a participant who finished
  bool autopilot = false;           // the simulated listener will answer
  LeaseHolder holder;               // who will run it (this_process())
};

struct OpenedSession {
  std::int64_t participant = 0, session = 0;
  bool resumed = false;
};

// The participant already finished and no new session was asked for.
class ParticipantFinished : public InputError {
 public:
  using InputError::InputError;
};

// Another running process holds the session's lease.
class SessionInUse : public InputError {
 public:
  using InputError::InputError;
};

// A session's completion, for the experimenter's overview.
struct SessionSummary {
  std::string study, participant_code;
  std::int64_t session = 0, started_ms = 0;
  std::optional<std::int64_t> finished_ms;
  std::int64_t trials = 0, responses = 0;
  bool autopilot = false;
};

// Where a stored row belongs: study, participant, session, block and trial (the export's key columns).
struct TrialContext {
  std::string study;
  std::int64_t participant = 0;
  std::string participant_code;
  bool export_personal = false;
  std::int64_t session = 0;
  bool autopilot = false;  // the session was answered by the simulated listener
  int block_index = 0;
  std::string block_id, block_type;
  int trial_index = 0;
};

// One response joined with everything needed to read it alone (the export's row).
struct ResponseRow : TrialContext {
  std::string stimuli_json;
  std::string value_json;
  double rt_ms = 0.0;
  int plays = 0;
  std::int64_t timestamp_ms = 0;
};

// One playback or staircase event joined with its trial (the export's events.csv row).
struct EventRow : TrialContext {
  std::string kind, stimulus, stimulus_hash, detail_json;
  std::int64_t timestamp_ms = 0;
};

// One scheduled trial with the recipe hashes of its stimuli (the export's trials.csv row).
struct TrialRow : TrialContext {
  std::string stimuli_json, hashes_json;
};

class ResultsStore {
 public:
  static constexpr int kSchemaVersion = kStoreSchemaVersion;
  static constexpr int kApplicationId = kStoreApplicationId;

  using Mode = StoreMode;

  // `location`: a file (SQLite) or a postgresql:// URI. Throws ms::InputError naming the location (a
  // URI without its password) if it is not a ModalStudy store, is damaged, has a newer schema or cannot
  // be reached; such a store is never modified. open_existing/read_only also refuse a missing store.
  // create_or_open treats an empty file (left by a creation that was killed or ran out of disk) as missing.
  explicit ResultsStore(const std::string& location, Mode mode = Mode::create_or_open);

  // In one transaction: adds the study (see add_study) and the participant if new, then resumes the
  // participant's unfinished session or starts one (recording `trials`), and leases it to
  // `request.holder`. Throws ParticipantFinished if the participant finished and !new_session,
  // SessionInUse if a live process holds the unfinished session, InputError if that session was
  // scheduled with another seed. Nothing is stored when it throws.
  OpenedSession open_session(const StudyRecord& study, const SessionRequest& request);
  // Renews the lease's heartbeat; throws SessionInUse if another process took the session over.
  void renew_lease(std::int64_t session, const LeaseHolder& holder, std::int64_t now_ms);
  void release_lease(std::int64_t session, const LeaseHolder& holder);

  // Adds the study, or checks an existing one with the same id has the same protocol hash.
  void add_study(const StudyRecord& study);
  std::int64_t add_participant(const std::string& study_id, const std::string& code, std::int64_t created_ms);
  std::int64_t start_session(std::int64_t participant, std::int64_t started_ms, std::uint64_t schedule_seed);
  void finish_session(std::int64_t session, std::int64_t finished_ms);
  // The whole schedule of a session, in one transaction.
  void record_trials(std::int64_t session, const std::vector<TrialRecord>& trials);

  // Commits the response in its own transaction and returns only after COMMIT. Throws StoreError
  // (refused()) if the trial already has a response (never overwrites) or was not scheduled.
  void record_response(std::int64_t session, const ResponseRecord& response);
  void record_event(std::int64_t session, const PlaybackEvent& event);

  // The first scheduled trial (in block, trial order) without a response; nullopt when all are done.
  std::optional<TrialPosition> first_unanswered_trial(std::int64_t session) const;

  std::optional<std::int64_t> find_participant(const std::string& study_id, const std::string& code) const;
  std::vector<std::string> participant_codes(const std::string& study_id) const;
  // The participant's most recent session without a finish time.
  std::optional<SessionRecord> unfinished_session(std::int64_t participant) const;
  // The participant's most recent session, finished or not.
  std::optional<SessionRecord> latest_session(std::int64_t participant) const;
  std::vector<SessionSummary> session_summaries() const;
  std::vector<TrialPosition> answered_trials(std::int64_t session) const;
  std::vector<PlaybackEvent> events(std::int64_t session, TrialPosition trial) const;  // in order

  std::vector<StudyRecord> studies() const;
  std::optional<ResponseRecord> response(std::int64_t session, TrialPosition trial) const;
  // The export's rows. Each throws InputError if it would return fewer rows than its table holds
  // (rows whose participant or study can no longer be joined): an export never drops rows silently.
  std::vector<ResponseRow> response_rows() const;  // ordered by session, block, trial
  std::vector<EventRow> event_rows() const;        // ordered by session, then as logged
  std::vector<TrialRow> trial_rows() const;        // ordered by session, block, trial
  std::int64_t count(const std::string& table) const;  // rows in one of the store's tables
  std::string integrity_check() const;                  // "ok" when the database's own check passes
  const std::string& path() const { return db_->location(); }  // the file, or the URI without password
  int schema_version() const { return schema_version_; }

 private:
  void insert_trials(std::int64_t session, const std::vector<TrialRecord>& trials);
  void check_lease(std::int64_t session, const LeaseHolder& holder, std::int64_t now_ms);
  // Runs `write` in one transaction of a session this process holds (refused when read-only or when
  // another process took the session over); committed only if `write` returns.
  void write_in_session(std::int64_t session, std::int64_t now_ms, const std::function<void()>& write);
  const char* autopilot_column() const;
  // The rows of one export query (TrialContext first, then `fill` reads the rest), all or an error.
  template <typename Row, typename Fill>
  std::vector<Row> context_rows(const char* table, const std::string& sql, Fill fill) const;  // "s.autopilot", or "0" in a read-only version-1 file

  std::unique_ptr<StoreConnection> db_;
  int schema_version_ = kSchemaVersion;
  LeaseHolder me_ = this_process();
  bool writable_ = false;
};

}  // namespace ms
