// ResultsStore: schema, opening checks and prepared statements; see results_store.hpp.
#include "studyapp/core/results_store.hpp"

#include <sqlite3.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>

#include "synthesis/input_error.hpp"

namespace ms {

namespace {

namespace fs = std::filesystem;

// Composite foreign keys tie responses and events to a scheduled trial: an answer to a trial that
// was never shown cannot be stored. UNIQUE on responses makes re-recording an error, not an update.
constexpr const char* kSchema = R"sql(
CREATE TABLE schema_version(version INTEGER NOT NULL);
CREATE TABLE studies(
  id TEXT PRIMARY KEY, title TEXT NOT NULL, protocol_sha256 TEXT NOT NULL, protocol_text TEXT NOT NULL,
  export_personal INTEGER NOT NULL DEFAULT 0 CHECK(export_personal IN (0, 1)));
CREATE TABLE participants(
  id INTEGER PRIMARY KEY, study TEXT NOT NULL REFERENCES studies(id), code TEXT NOT NULL,
  created INTEGER NOT NULL, UNIQUE(study, code));
CREATE TABLE sessions(
  id INTEGER PRIMARY KEY, participant INTEGER NOT NULL REFERENCES participants(id),
  started INTEGER NOT NULL, finished INTEGER, schedule_seed INTEGER NOT NULL);
CREATE TABLE trials(
  session INTEGER NOT NULL REFERENCES sessions(id), block_index INTEGER NOT NULL, block_id TEXT NOT NULL,
  block_type TEXT NOT NULL, trial_index INTEGER NOT NULL,
  stimuli TEXT NOT NULL CHECK(json_valid(stimuli)), stimulus_hashes TEXT NOT NULL CHECK(json_valid(stimulus_hashes)),
  PRIMARY KEY(session, block_index, trial_index));
CREATE TABLE responses(
  id INTEGER PRIMARY KEY, session INTEGER NOT NULL, block_index INTEGER NOT NULL, trial_index INTEGER NOT NULL,
  value TEXT NOT NULL CHECK(json_valid(value)), rt_ms REAL NOT NULL, plays INTEGER NOT NULL,
  timestamp INTEGER NOT NULL,
  UNIQUE(session, block_index, trial_index),
  FOREIGN KEY(session, block_index, trial_index) REFERENCES trials(session, block_index, trial_index));
CREATE TABLE events(
  id INTEGER PRIMARY KEY, session INTEGER NOT NULL, block_index INTEGER NOT NULL, trial_index INTEGER NOT NULL,
  kind TEXT NOT NULL CHECK(kind IN ('play', 'stop', 'switch', 'step')), stimulus TEXT NOT NULL,
  timestamp_ms INTEGER NOT NULL, detail TEXT CHECK(detail IS NULL OR json_valid(detail)),
  FOREIGN KEY(session, block_index, trial_index) REFERENCES trials(session, block_index, trial_index));
CREATE INDEX events_by_trial ON events(session, block_index, trial_index);
)sql";

[[noreturn]] void not_ours(const std::string& path, const std::string& why) {
  throw InputError(SourceLocation{path, 0, 0}, "not a ModalStudy results database (" + why + ")");
}

// Checks the first bytes before SQLite sees the file, so a stray CSV or WAV is refused untouched.
void check_header(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(SourceLocation{path, 0, 0}, "no such file");
  if (!fs::is_regular_file(path, ec)) not_ours(path, "not a regular file");
  std::array<char, 16> head{};
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path, 0, 0}, "cannot read file");
  in.read(head.data(), head.size());
  if (in.gcount() != std::streamsize(head.size()) || std::string(head.data(), 15) != "SQLite format 3")
    not_ours(path, "not an SQLite file");
}

std::string json_array(const std::vector<std::string>& items) { return nlohmann::json(items).dump(); }

// The first nine columns of the export queries: study, participant id and code, export_personal,
// session, block index, id and type, trial index.
void read_context(const sqlite::Statement& q, TrialContext& row) {
  row.study = q.column_text(0);
  row.participant = q.column_int64(1);
  row.participant_code = q.column_text(2);
  row.export_personal = q.column_int64(3) != 0;
  row.session = q.column_int64(4);
  row.block_index = int(q.column_int64(5));
  row.block_id = q.column_text(6);
  row.block_type = q.column_text(7);
  row.trial_index = int(q.column_int64(8));
}

}  // namespace

std::string to_string(EventKind kind) {
  switch (kind) {
    case EventKind::play: return "play";
    case EventKind::stop: return "stop";
    case EventKind::switch_to: return "switch";
    case EventKind::step: return "step";
  }
  return "play";
}

ResultsStore::ResultsStore(const std::string& path, Mode mode)
    : created_(mode == Mode::create_or_open && !fs::exists(path)),
      db_([&] {
        if (!created_) check_header(path);
        int flags = mode == Mode::read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE;
        if (created_) flags |= SQLITE_OPEN_CREATE;
        try {
          return sqlite::Database(path, flags);
        } catch (const sqlite::Error& e) {  // e.g. a missing folder: the person's path is wrong
          throw InputError(SourceLocation{path, 0, 0}, "cannot open results database: " + std::string(e.what()));
        }
      }()) {
  try {
    sqlite::Statement probe(db_, "SELECT count(*) FROM sqlite_schema");
    probe.step();
  } catch (const sqlite::Error&) {
    not_ours(path, "SQLite cannot read it");
  }
  db_.exec("PRAGMA busy_timeout=5000; PRAGMA foreign_keys=ON");
  if (created_) {
    // Built in rollback-journal mode so the main file holds the header and schema from the start.
    sqlite::Transaction tx(db_);
    db_.exec(kSchema);
    db_.exec("PRAGMA application_id=" + std::to_string(kApplicationId));
    db_.exec("INSERT INTO schema_version(version) VALUES (" + std::to_string(kSchemaVersion) + ")");
    tx.commit();
  } else {
    // Only reads until the file is known to be ours and of a version this program understands.
    sqlite::Statement app(db_, "PRAGMA application_id");
    app.step();
    if (app.column_int64(0) != kApplicationId) not_ours(path, "another application's SQLite file");
    sqlite::Statement version(db_, "SELECT max(version) FROM schema_version");
    version.step();
    const std::int64_t v = version.column_int64(0);
    if (v > kSchemaVersion)
      throw InputError(SourceLocation{path, 0, 0}, "schema version " + std::to_string(v) +
                                                       " is newer than this program supports (" +
                                                       std::to_string(kSchemaVersion) + "); update ModalStudy");
  }
  if (mode != Mode::read_only) {
    // WAL: a commit appends to the log, readers (an export during a session) never block the writer.
    // synchronous=FULL: WAL with NORMAL survives a program crash but may lose the last commits on
    // power loss; FULL fsyncs the log at every COMMIT, so an answer acknowledged to the participant
    // is on disk before the next trial is shown, at ~1 fsync per response (see bench_results_store).
    db_.exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL");
    insert_response_.emplace(db_,
                             "INSERT INTO responses(session, block_index, trial_index, value, rt_ms, plays, timestamp) "
                             "VALUES (?, ?, ?, ?, ?, ?, ?)");
    insert_event_.emplace(db_,
                          "INSERT INTO events(session, block_index, trial_index, kind, stimulus, timestamp_ms, "
                          "detail) VALUES (?, ?, ?, ?, ?, ?, ?)");
  }
}

void ResultsStore::add_study(const StudyRecord& study) {
  sqlite::Statement find(db_, "SELECT protocol_sha256 FROM studies WHERE id = ?");
  find.bind(1, study.id);
  if (find.step()) {
    if (find.column_text(0) != study.protocol_sha256)
      throw InputError(SourceLocation{path(), 0, 0}, "study '" + study.id +
                                                         "' is already stored with a different protocol (sha256 " +
                                                         find.column_text(0) + ")");
    return;
  }
  sqlite::Statement insert(
      db_, "INSERT INTO studies(id, title, protocol_sha256, protocol_text, export_personal) VALUES (?, ?, ?, ?, ?)");
  insert.bind(1, study.id).bind(2, study.title).bind(3, study.protocol_sha256).bind(4, study.protocol_text);
  insert.bind(5, study.export_personal ? 1 : 0).run();
}

std::int64_t ResultsStore::add_participant(const std::string& study_id, const std::string& code,
                                           std::int64_t created_ms) {
  sqlite::Statement insert(db_, "INSERT INTO participants(study, code, created) VALUES (?, ?, ?)");
  insert.bind(1, study_id).bind(2, code).bind(3, created_ms).run();
  return db_.last_insert_rowid();
}

std::int64_t ResultsStore::start_session(std::int64_t participant, std::int64_t started_ms,
                                         std::uint64_t schedule_seed) {
  sqlite::Statement insert(db_, "INSERT INTO sessions(participant, started, schedule_seed) VALUES (?, ?, ?)");
  // SQLite integers are signed 64-bit; the seed is stored bit for bit.
  insert.bind(1, participant).bind(2, started_ms).bind(3, static_cast<std::int64_t>(schedule_seed)).run();
  return db_.last_insert_rowid();
}

void ResultsStore::finish_session(std::int64_t session, std::int64_t finished_ms) {
  sqlite::Statement update(db_, "UPDATE sessions SET finished = ? WHERE id = ?");
  update.bind(1, finished_ms).bind(2, session).run();
}

void ResultsStore::record_trials(std::int64_t session, const std::vector<TrialRecord>& trials) {
  sqlite::Transaction tx(db_);
  sqlite::Statement insert(db_,
                           "INSERT INTO trials(session, block_index, block_id, block_type, trial_index, stimuli, "
                           "stimulus_hashes) VALUES (?, ?, ?, ?, ?, ?, ?)");
  for (const TrialRecord& t : trials) {
    insert.bind(1, session).bind(2, t.block_index).bind(3, t.block_id).bind(4, t.block_type).bind(5, t.trial_index);
    insert.bind(6, json_array(t.stimuli)).bind(7, json_array(t.stimulus_hashes)).run();
  }
  tx.commit();
}

void ResultsStore::record_response(std::int64_t session, const ResponseRecord& r) {
  if (!insert_response_) throw sqlite::Error(path() + ": opened read-only", SQLITE_READONLY);
  // One INSERT in autocommit mode is one transaction: sqlite3_step returns SQLITE_DONE only after
  // the COMMIT (and, with synchronous=FULL, the fsync of the WAL) has completed.
  insert_response_->bind(1, session).bind(2, r.trial.block_index).bind(3, r.trial.trial_index);
  insert_response_->bind(4, r.value_json).bind(5, r.rt_ms).bind(6, r.plays).bind(7, r.timestamp_ms);
  try {
    insert_response_->run();
  } catch (const sqlite::Error& e) {
    insert_response_->reset();
    if (e.code() == SQLITE_CONSTRAINT)
      throw sqlite::Error(path() + ": cannot record response to session " + std::to_string(session) + " block " +
                              std::to_string(r.trial.block_index) + " trial " + std::to_string(r.trial.trial_index) +
                              " (already answered, not scheduled, or value not JSON): " + e.what(),
                          e.code());
    throw;
  }
}

void ResultsStore::record_event(std::int64_t session, const PlaybackEvent& e) {
  if (!insert_event_) throw sqlite::Error(path() + ": opened read-only", SQLITE_READONLY);
  insert_event_->bind(1, session).bind(2, e.trial.block_index).bind(3, e.trial.trial_index);
  insert_event_->bind(4, to_string(e.kind)).bind(5, e.stimulus).bind(6, e.timestamp_ms);
  if (e.detail_json.empty())
    insert_event_->bind_null(7);
  else
    insert_event_->bind(7, e.detail_json);
  try {
    insert_event_->run();
  } catch (...) {
    insert_event_->reset();
    throw;
  }
}

std::optional<TrialPosition> ResultsStore::first_unanswered_trial(std::int64_t session) const {
  sqlite::Statement q(db_,
                      "SELECT t.block_index, t.trial_index FROM trials t LEFT JOIN responses r "
                      "ON r.session = t.session AND r.block_index = t.block_index AND r.trial_index = t.trial_index "
                      "WHERE t.session = ? AND r.id IS NULL ORDER BY t.block_index, t.trial_index LIMIT 1");
  q.bind(1, session);
  if (!q.step()) return std::nullopt;
  return TrialPosition{int(q.column_int64(0)), int(q.column_int64(1))};
}

std::optional<std::int64_t> ResultsStore::find_participant(const std::string& study_id,
                                                           const std::string& code) const {
  sqlite::Statement q(db_, "SELECT id FROM participants WHERE study = ? AND code = ?");
  q.bind(1, study_id).bind(2, code);
  if (!q.step()) return std::nullopt;
  return q.column_int64(0);
}

std::optional<SessionRecord> ResultsStore::unfinished_session(std::int64_t participant) const {
  sqlite::Statement q(db_,
                      "SELECT id, participant, started, finished, schedule_seed FROM sessions "
                      "WHERE participant = ? AND finished IS NULL ORDER BY id DESC LIMIT 1");
  q.bind(1, participant);
  if (!q.step()) return std::nullopt;
  return SessionRecord{q.column_int64(0), q.column_int64(1), q.column_int64(2), std::nullopt,
                       static_cast<std::uint64_t>(q.column_int64(4))};
}

std::vector<SessionSummary> ResultsStore::session_summaries() const {
  sqlite::Statement q(db_,
                      "SELECT p.study, p.code, s.id, s.started, s.finished, "
                      "(SELECT count(*) FROM trials t WHERE t.session = s.id), "
                      "(SELECT count(*) FROM responses r WHERE r.session = s.id) "
                      "FROM sessions s JOIN participants p ON p.id = s.participant ORDER BY s.id");
  std::vector<SessionSummary> out;
  while (q.step()) {
    SessionSummary row;
    row.study = q.column_text(0);
    row.participant_code = q.column_text(1);
    row.session = q.column_int64(2);
    row.started_ms = q.column_int64(3);
    if (!q.is_null(4)) row.finished_ms = q.column_int64(4);
    row.trials = q.column_int64(5);
    row.responses = q.column_int64(6);
    out.push_back(std::move(row));
  }
  return out;
}

std::vector<TrialPosition> ResultsStore::answered_trials(std::int64_t session) const {
  sqlite::Statement q(db_, "SELECT block_index, trial_index FROM responses WHERE session = ?");
  q.bind(1, session);
  std::vector<TrialPosition> out;
  while (q.step()) out.push_back({int(q.column_int64(0)), int(q.column_int64(1))});
  return out;
}

std::vector<PlaybackEvent> ResultsStore::events(std::int64_t session, TrialPosition trial) const {
  sqlite::Statement q(db_,
                      "SELECT kind, stimulus, timestamp_ms, coalesce(detail, '') FROM events "
                      "WHERE session = ? AND block_index = ? AND trial_index = ? ORDER BY id");
  q.bind(1, session).bind(2, trial.block_index).bind(3, trial.trial_index);
  std::vector<PlaybackEvent> out;
  while (q.step()) {
    const std::string kind = q.column_text(0);
    PlaybackEvent e;
    e.trial = trial;
    e.kind = kind == "stop" ? EventKind::stop
             : kind == "switch" ? EventKind::switch_to
             : kind == "step"   ? EventKind::step
                                : EventKind::play;
    e.stimulus = q.column_text(1);
    e.timestamp_ms = q.column_int64(2);
    e.detail_json = q.column_text(3);
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<EventRow> ResultsStore::event_rows() const {
  sqlite::Statement q(db_,
                      "SELECT p.study, p.id, p.code, st.export_personal, e.session, e.block_index, t.block_id, "
                      "t.block_type, e.trial_index, e.kind, e.stimulus, t.stimuli, t.stimulus_hashes, "
                      "coalesce(e.detail, ''), e.timestamp_ms "
                      "FROM events e JOIN trials t USING (session, block_index, trial_index) "
                      "JOIN sessions s ON s.id = e.session JOIN participants p ON p.id = s.participant "
                      "JOIN studies st ON st.id = p.study ORDER BY e.session, e.id");
  std::vector<EventRow> rows;
  while (q.step()) {
    EventRow row;
    read_context(q, row);
    row.kind = q.column_text(9);
    row.stimulus = q.column_text(10);
    // The hash of the played stimulus, looked up among the trial's stimuli (a slider or staircase
    // variant carries its own hash in the detail instead).
    const auto names = nlohmann::json::parse(q.column_text(11));
    const auto hashes = nlohmann::json::parse(q.column_text(12));
    for (std::size_t i = 0; i < names.size() && i < hashes.size(); ++i)
      if (names[i] == row.stimulus) row.stimulus_hash = hashes[i].get<std::string>();
    row.detail_json = q.column_text(13);
    row.timestamp_ms = q.column_int64(14);
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<TrialRow> ResultsStore::trial_rows() const {
  sqlite::Statement q(db_,
                      "SELECT p.study, p.id, p.code, st.export_personal, t.session, t.block_index, t.block_id, "
                      "t.block_type, t.trial_index, t.stimuli, t.stimulus_hashes "
                      "FROM trials t JOIN sessions s ON s.id = t.session JOIN participants p ON p.id = s.participant "
                      "JOIN studies st ON st.id = p.study ORDER BY t.session, t.block_index, t.trial_index");
  std::vector<TrialRow> rows;
  while (q.step()) {
    TrialRow row;
    read_context(q, row);
    row.stimuli_json = q.column_text(9);
    row.hashes_json = q.column_text(10);
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<StudyRecord> ResultsStore::studies() const {
  sqlite::Statement q(db_, "SELECT id, title, protocol_sha256, protocol_text, export_personal FROM studies ORDER BY id");
  std::vector<StudyRecord> out;
  while (q.step())
    out.push_back({q.column_text(0), q.column_text(1), q.column_text(2), q.column_text(3), q.column_int64(4) != 0});
  return out;
}

std::optional<ResponseRecord> ResultsStore::response(std::int64_t session, TrialPosition trial) const {
  sqlite::Statement q(db_,
                      "SELECT value, rt_ms, plays, timestamp FROM responses "
                      "WHERE session = ? AND block_index = ? AND trial_index = ?");
  q.bind(1, session).bind(2, trial.block_index).bind(3, trial.trial_index);
  if (!q.step()) return std::nullopt;
  return ResponseRecord{trial, q.column_text(0), q.column_double(1), int(q.column_int64(2)), q.column_int64(3)};
}

std::vector<ResponseRow> ResultsStore::response_rows() const {
  sqlite::Statement q(db_,
                      "SELECT p.study, p.id, p.code, st.export_personal, r.session, r.block_index, t.block_id, "
                      "t.block_type, r.trial_index, t.stimuli, r.value, r.rt_ms, r.plays, r.timestamp "
                      "FROM responses r JOIN trials t USING (session, block_index, trial_index) "
                      "JOIN sessions s ON s.id = r.session JOIN participants p ON p.id = s.participant "
                      "JOIN studies st ON st.id = p.study ORDER BY r.session, r.block_index, r.trial_index");
  std::vector<ResponseRow> rows;
  while (q.step()) {
    ResponseRow row;
    read_context(q, row);
    row.stimuli_json = q.column_text(9);
    row.value_json = q.column_text(10);
    row.rt_ms = q.column_double(11);
    row.plays = int(q.column_int64(12));
    row.timestamp_ms = q.column_int64(13);
    rows.push_back(std::move(row));
  }
  return rows;
}

std::int64_t ResultsStore::count(const std::string& table) const {
  static const std::array<std::string, 6> known{"studies", "participants", "sessions", "trials", "responses", "events"};
  if (std::find(known.begin(), known.end(), table) == known.end())
    throw std::invalid_argument("ResultsStore::count: unknown table '" + table + "'");
  sqlite::Statement q(db_, "SELECT count(*) FROM " + table);
  q.step();
  return q.column_int64(0);
}

std::string ResultsStore::integrity_check() const {
  sqlite::Statement q(db_, "PRAGMA integrity_check");
  std::string out;
  while (q.step()) out += (out.empty() ? "" : "; ") + q.column_text(0);
  return out;
}

}  // namespace ms
