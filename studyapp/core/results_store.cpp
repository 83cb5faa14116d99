// ResultsStore: schema, opening checks and prepared statements; see results_store.hpp.
#include "studyapp/core/results_store.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sqlite3.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
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

constexpr const char* kLeaseSchema = R"sql(
CREATE TABLE leases(
  session INTEGER PRIMARY KEY REFERENCES sessions(id), host TEXT NOT NULL, pid INTEGER NOT NULL,
  process_start TEXT NOT NULL, acquired_ms INTEGER NOT NULL, heartbeat_ms INTEGER NOT NULL);
)sql";

// Version 1 -> 2: sessions say whether the simulated listener answered; sessions can be leased.
constexpr const char* kMigrateTo2 =
    "ALTER TABLE sessions ADD COLUMN autopilot INTEGER NOT NULL DEFAULT 0 CHECK(autopilot IN (0, 1));";

[[noreturn]] void not_ours(const std::string& path, const std::string& why) {
  throw InputError(SourceLocation{path, 0, 0}, "not a ModalStudy results database (" + why + ")");
}

[[noreturn]] void damaged(const std::string& path, const std::string& report) {
  throw InputError(SourceLocation{path, 0, 0},
                   "the results database is damaged (" + report.substr(0, 200) +
                       "); it was not modified. Keep a copy, then recover what is readable with: sqlite3 " + path +
                       " .recover | sqlite3 recovered.sqlite");
}

std::string folder_of(const std::string& path) {
  const fs::path dir = fs::path(path).parent_path();
  return dir.empty() ? std::string(".") : dir.string();
}

// Checks the first bytes before SQLite sees the file, so a stray CSV or WAV is refused untouched.
void check_header(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(SourceLocation{path, 0, 0}, "no such file");
  if (!fs::is_regular_file(path, ec)) not_ours(path, "not a regular file");
  std::array<char, 16> head{};
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path, 0, 0}, "cannot read file (permission denied?)");
  in.read(head.data(), head.size());
  if (in.gcount() != std::streamsize(head.size()) || std::string(head.data(), 15) != "SQLite format 3")
    not_ours(path, "not an SQLite file");
}

bool pid_alive(long pid) { return kill(pid_t(pid), 0) == 0 || errno == EPERM; }

// Temporary files of creations that were killed: ".NAME.new-PID" whose PID is gone.
void remove_abandoned_temporaries(const std::string& path) {
  const fs::path p(path);
  const std::string prefix = "." + p.filename().string() + ".new-";
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder_of(path), ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const long pid = std::atol(name.c_str() + prefix.size());
    if (pid > 0 && !pid_alive(pid)) fs::remove(entry.path(), ec);
  }
}

void fsync_folder(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

// Makes `path` a complete, empty results database, atomically: the schema is built in a temporary
// file beside it and linked into place only when complete, so a kill or a full disk at any moment
// leaves either no file or a whole one. An empty file at `path` (what such an interrupted creation
// left before) counts as missing. Another process creating the same file at the same time wins or
// loses the link; both then open the one file.
void create_atomically(const std::string& path) {
  std::error_code ec;
  if (fs::exists(path, ec)) {
    if (!fs::is_regular_file(path, ec) || fs::file_size(path, ec) != 0) return;
    // An empty main file cannot hold a database, so nothing beside it belongs to one either; a stale
    // rollback journal left here would otherwise be played back onto the new file.
    for (const char* side : {"", "-journal", "-wal", "-shm"}) fs::remove(path + side, ec);
  }
  const std::string dir = folder_of(path);
  if (!fs::is_directory(dir, ec))
    throw InputError(SourceLocation{path, 0, 0}, "cannot create the results database: folder " + dir + " does not exist");
  if (access(dir.c_str(), W_OK) != 0)
    throw InputError(SourceLocation{path, 0, 0},
                     "cannot create the results database: no permission to write in folder " + dir);
  remove_abandoned_temporaries(path);
  const std::string temp =
      (fs::path(dir) / ("." + fs::path(path).filename().string() + ".new-" + std::to_string(getpid()))).string();
  auto discard = [&] {
    for (const char* side : {"", "-journal", "-wal", "-shm"}) fs::remove(temp + side, ec);
  };
  discard();
  try {
    sqlite::Database db(temp, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
    db.exec("PRAGMA synchronous=FULL");
    sqlite::Transaction tx(db);
    db.exec(kSchema);
    db.exec(kLeaseSchema);
    db.exec(kMigrateTo2);
    db.exec("PRAGMA application_id=" + std::to_string(ResultsStore::kApplicationId));
    db.exec("INSERT INTO schema_version(version) VALUES (" + std::to_string(ResultsStore::kSchemaVersion) + ")");
    tx.commit();
    db.exec("PRAGMA journal_mode=WAL");  // recorded in the header; the log is removed on close
  } catch (const sqlite::Error& e) {
    discard();
    throw InputError(SourceLocation{path, 0, 0},
                     std::string("cannot create the results database (disk full?): ") + e.what());
  }
  const int linked = ::link(temp.c_str(), path.c_str());
  const int link_errno = errno;
  discard();
  if (linked != 0 && link_errno != EEXIST)
    throw InputError(SourceLocation{path, 0, 0},
                     std::string("cannot create the results database: ") + std::strerror(link_errno));
  fsync_folder(dir);
}

// PRAGMA quick_check (or the slower integrity_check) on a connection of its own that only reads, so
// a damaged file is judged before anything could write to it.
void check_intact(const std::string& path, bool thorough) {
  std::string report;
  try {
    sqlite::Database db(path, SQLITE_OPEN_READONLY);
    db.exec("PRAGMA query_only=1");
    sqlite::Statement q(db, thorough ? "PRAGMA integrity_check" : "PRAGMA quick_check");
    while (q.step()) report += (report.empty() ? "" : "; ") + q.column_text(0);
  } catch (const sqlite::Error& e) {
    if (e.code() == SQLITE_CORRUPT || e.code() == SQLITE_NOTADB) damaged(path, e.what());
    if (e.code() == SQLITE_CANTOPEN)
      throw InputError(SourceLocation{path, 0, 0},
                       "cannot open the results database: SQLite must create " + fs::path(path).filename().string() +
                           "-shm beside it and has no permission to write in folder " + folder_of(path) +
                           "; make the folder writable or copy the database to one that is");
    not_ours(path, std::string("SQLite cannot read it: ") + e.what());
  }
  if (report != "ok") damaged(path, report);
}

// Unix milliseconds as a UTC date, e.g. 2026-12-01.
std::string utc_date(std::int64_t unix_ms) {
  const std::time_t t = static_cast<std::time_t>(unix_ms / 1000);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[16];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
  return buf;
}

// Refuses an export that would silently miss rows the table holds.
void check_complete(const std::string& path, const char* table, std::int64_t stored, std::size_t joined) {
  if (std::int64_t(joined) != stored)
    throw InputError(SourceLocation{path, 0, 0},
                     std::string("the results database is inconsistent: ") + table + " holds " +
                         std::to_string(stored) + " rows but only " + std::to_string(joined) +
                         " belong to a stored participant and study; nothing was exported");
}

std::string json_array(const std::vector<std::string>& items) { return nlohmann::json(items).dump(); }

// The first ten columns of the export queries: study, participant id and code, export_personal,
// session, block index, id and type, trial index, autopilot.
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
  row.autopilot = q.column_int64(9) != 0;
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
    : db_([&] {
        if (mode == Mode::create_or_open) create_atomically(path);
        check_header(path);
        if (mode != Mode::read_only && access(folder_of(path).c_str(), W_OK) != 0)
          throw InputError(SourceLocation{path, 0, 0},
                           "cannot write to the results database: SQLite keeps its write-ahead log (" +
                               fs::path(path).filename().string() + "-wal, -shm) beside it and has no permission "
                               "to write in folder " + folder_of(path));
        check_intact(path, mode == Mode::read_only);
        const int flags = mode == Mode::read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE;
        try {
          return sqlite::Database(path, flags);
        } catch (const sqlite::Error& e) {
          throw InputError(SourceLocation{path, 0, 0}, "cannot open results database: " + std::string(e.what()));
        }
      }()) {
  db_.exec("PRAGMA busy_timeout=5000; PRAGMA foreign_keys=ON");
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
  schema_version_ = int(v);
  if (mode == Mode::read_only) return;
  writable_ = true;
  // WAL: a commit appends to the log, readers (an export during a session) never block the writer.
  // synchronous=FULL: WAL with NORMAL survives a program crash but may lose the last commits on
  // power loss; FULL fsyncs the log at every COMMIT, so an answer acknowledged to the participant
  // is on disk before the next trial is shown, at ~1 fsync per response (see bench_results_store).
  db_.exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL");
  if (schema_version_ < 2) {
    sqlite::Transaction tx(db_);
    sqlite::Statement again(db_, "SELECT max(version) FROM schema_version");  // another process may have
    again.step();                                                            // migrated meanwhile
    if (again.column_int64(0) < 2) {
      db_.exec(kMigrateTo2);
      db_.exec(kLeaseSchema);
      db_.exec("INSERT INTO schema_version(version) VALUES (2)");
    }
    tx.commit();
    schema_version_ = 2;
  }
}

const char* ResultsStore::autopilot_column() const { return schema_version_ >= 2 ? "s.autopilot" : "0"; }

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

void ResultsStore::insert_trials(std::int64_t session, const std::vector<TrialRecord>& trials) {
  sqlite::Statement insert(db_,
                           "INSERT INTO trials(session, block_index, block_id, block_type, trial_index, stimuli, "
                           "stimulus_hashes) VALUES (?, ?, ?, ?, ?, ?, ?)");
  for (const TrialRecord& t : trials) {
    insert.bind(1, session).bind(2, t.block_index).bind(3, t.block_id).bind(4, t.block_type).bind(5, t.trial_index);
    insert.bind(6, json_array(t.stimuli)).bind(7, json_array(t.stimulus_hashes)).run();
  }
}

void ResultsStore::record_trials(std::int64_t session, const std::vector<TrialRecord>& trials) {
  sqlite::Transaction tx(db_);
  insert_trials(session, trials);
  tx.commit();
}

OpenedSession ResultsStore::open_session(const StudyRecord& study, const SessionRequest& r) {
  // BEGIN IMMEDIATE: a second process opening the same participant waits here (busy_timeout) and
  // then sees the first one's participant, session and lease instead of racing it to the INSERTs.
  sqlite::Transaction tx(db_);
  add_study(study);
  OpenedSession out;
  const auto known = find_participant(r.study_id, r.participant);
  out.participant = known ? *known : add_participant(r.study_id, r.participant, r.now_ms);
  const auto open = known ? unfinished_session(out.participant) : std::nullopt;
  if (open) {
    // Same protocol text (checked by add_study) and participant give the same schedule; the stored
    // seed guards against a schedule algorithm that changed between versions.
    if (open->schedule_seed != r.schedule_seed)
      throw InputError(SourceLocation{path(), 0, 0},
                       "session " + std::to_string(open->id) + " of participant '" + r.participant +
                           "' was scheduled with another seed; start a new database for this version");
    sqlite::Statement lease(db_, "SELECT host, pid, process_start, heartbeat_ms FROM leases WHERE session = ?");
    lease.bind(1, open->id);
    if (lease.step()) {
      const LeaseHolder holder{lease.column_text(0), lease.column_int64(1), lease.column_text(2)};
      if (!(holder == r.holder) && !lease_is_stale(holder, lease.column_int64(3), r.now_ms))
        throw SessionInUse(SourceLocation{path(), 0, 0},
                           "participant '" + r.participant + "' is being run right now by " + describe(holder) +
                               " (session " + std::to_string(open->id) + ", last sign of life " +
                               std::to_string((r.now_ms - lease.column_int64(3)) / 1000) +
                               " s ago); finish or close that run first");
    }
    out.session = open->id;
    out.resumed = true;
    if (r.autopilot) {
      sqlite::Statement mark(db_, "UPDATE sessions SET autopilot = 1 WHERE id = ?");
      mark.bind(1, out.session).run();
    }
  } else {
    if (known && !r.new_session)
      if (const auto last = latest_session(out.participant); last && last->finished_ms) {
        sqlite::Statement n(db_,
                            "SELECT (SELECT count(*) FROM responses WHERE session = ?1), "
                            "(SELECT count(*) FROM trials WHERE session = ?1)");
        n.bind(1, last->id);
        n.step();
        throw ParticipantFinished(SourceLocation{path(), 0, 0},
                                  r.participant + " finished this study on " +
                                      utc_date(*last->finished_ms) + " (" +
                                      std::to_string(n.column_int64(0)) + "/" + std::to_string(n.column_int64(1)) +
                                      " trials); use --new-session to run it again");
      }
    sqlite::Statement insert(db_,
                             "INSERT INTO sessions(participant, started, schedule_seed, autopilot) VALUES (?, ?, ?, ?)");
    // SQLite integers are signed 64-bit; the seed is stored bit for bit.
    insert.bind(1, out.participant).bind(2, r.now_ms).bind(3, static_cast<std::int64_t>(r.schedule_seed));
    insert.bind(4, r.autopilot ? 1 : 0).run();
    out.session = db_.last_insert_rowid();
    insert_trials(out.session, r.trials);
  }
  sqlite::Statement take(db_,
                         "INSERT INTO leases(session, host, pid, process_start, acquired_ms, heartbeat_ms) "
                         "VALUES (?1, ?2, ?3, ?4, ?5, ?5) ON CONFLICT(session) DO UPDATE SET host = ?2, pid = ?3, "
                         "process_start = ?4, acquired_ms = ?5, heartbeat_ms = ?5");
  take.bind(1, out.session).bind(2, r.holder.host).bind(3, r.holder.pid).bind(4, r.holder.process_start);
  take.bind(5, r.now_ms).run();
  tx.commit();
  return out;
}

// Inside a write transaction: refuses to write for a session whose lease another process holds (it
// took over a lease it judged stale), and renews the heartbeat of our own. Sessions never leased
// (stores written directly, e.g. by tools) are not checked.
void ResultsStore::check_lease(std::int64_t session, const LeaseHolder& holder, std::int64_t now_ms) {
  sqlite::Statement q(db_, "SELECT host, pid, process_start FROM leases WHERE session = ?");
  q.bind(1, session);
  if (!q.step()) return;
  const LeaseHolder owner{q.column_text(0), q.column_int64(1), q.column_text(2)};
  q.reset();
  if (!(owner == holder))
    throw SessionInUse(SourceLocation{path(), 0, 0}, "session " + std::to_string(session) +
                                                         " is now run by " + describe(owner) +
                                                         "; this run stops without storing more");
  sqlite::Statement beat(db_, "UPDATE leases SET heartbeat_ms = ? WHERE session = ?");
  beat.bind(1, now_ms).bind(2, session).run();
}

void ResultsStore::renew_lease(std::int64_t session, const LeaseHolder& holder, std::int64_t now_ms) {
  sqlite::Transaction tx(db_);
  check_lease(session, holder, now_ms);
  tx.commit();
}

void ResultsStore::release_lease(std::int64_t session, const LeaseHolder& holder) {
  sqlite::Statement q(db_, "DELETE FROM leases WHERE session = ? AND host = ? AND pid = ? AND process_start = ?");
  q.bind(1, session).bind(2, holder.host).bind(3, holder.pid).bind(4, holder.process_start).run();
}

void ResultsStore::write_in_session(std::int64_t session, std::int64_t now_ms, const std::function<void()>& write) {
  if (!writable_) throw sqlite::Error(path() + ": opened read-only", SQLITE_READONLY);
  // One transaction per write: COMMIT returns only after the WAL is fsynced (synchronous=FULL).
  sqlite::Transaction tx(db_);
  check_lease(session, me_, now_ms);
  write();
  tx.commit();
}

void ResultsStore::record_response(std::int64_t session, const ResponseRecord& r) {
  write_in_session(session, r.timestamp_ms, [&] {
    sqlite::Statement insert(db_,
                             "INSERT INTO responses(session, block_index, trial_index, value, rt_ms, plays, timestamp) "
                             "VALUES (?, ?, ?, ?, ?, ?, ?)");
    insert.bind(1, session).bind(2, r.trial.block_index).bind(3, r.trial.trial_index);
    insert.bind(4, r.value_json).bind(5, r.rt_ms).bind(6, r.plays).bind(7, r.timestamp_ms);
    try {
      insert.run();
    } catch (const sqlite::Error& e) {
      if (e.code() == SQLITE_CONSTRAINT)
        throw sqlite::Error(path() + ": cannot record response to session " + std::to_string(session) + " block " +
                                std::to_string(r.trial.block_index) + " trial " + std::to_string(r.trial.trial_index) +
                                " (already answered, not scheduled, or value not JSON): " + e.what(),
                            e.code());
      throw;
    }
  });
}

void ResultsStore::record_event(std::int64_t session, const PlaybackEvent& e) {
  write_in_session(session, e.timestamp_ms, [&] {
    sqlite::Statement insert(db_,
                             "INSERT INTO events(session, block_index, trial_index, kind, stimulus, timestamp_ms, "
                             "detail) VALUES (?, ?, ?, ?, ?, ?, ?)");
    insert.bind(1, session).bind(2, e.trial.block_index).bind(3, e.trial.trial_index);
    insert.bind(4, to_string(e.kind)).bind(5, e.stimulus).bind(6, e.timestamp_ms);
    if (e.detail_json.empty())
      insert.bind_null(7);
    else
      insert.bind(7, e.detail_json);
    insert.run();
  });
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

std::vector<std::string> ResultsStore::participant_codes(const std::string& study_id) const {
  sqlite::Statement q(db_, "SELECT code FROM participants WHERE study = ? ORDER BY id");
  q.bind(1, study_id);
  std::vector<std::string> out;
  while (q.step()) out.push_back(q.column_text(0));
  return out;
}

namespace {

std::optional<SessionRecord> read_session(sqlite::Statement& q) {
  if (!q.step()) return std::nullopt;
  SessionRecord r{q.column_int64(0), q.column_int64(1), q.column_int64(2), std::nullopt,
                  static_cast<std::uint64_t>(q.column_int64(4)), q.column_int64(5) != 0};
  if (!q.is_null(3)) r.finished_ms = q.column_int64(3);
  return r;
}

}  // namespace

std::optional<SessionRecord> ResultsStore::unfinished_session(std::int64_t participant) const {
  sqlite::Statement q(db_, "SELECT s.id, s.participant, s.started, s.finished, s.schedule_seed, " +
                               std::string(autopilot_column()) +
                               " FROM sessions s WHERE s.participant = ? AND s.finished IS NULL ORDER BY s.id DESC LIMIT 1");
  q.bind(1, participant);
  return read_session(q);
}

std::optional<SessionRecord> ResultsStore::latest_session(std::int64_t participant) const {
  sqlite::Statement q(db_, "SELECT s.id, s.participant, s.started, s.finished, s.schedule_seed, " +
                               std::string(autopilot_column()) +
                               " FROM sessions s WHERE s.participant = ? ORDER BY s.id DESC LIMIT 1");
  q.bind(1, participant);
  return read_session(q);
}

std::vector<SessionSummary> ResultsStore::session_summaries() const {
  sqlite::Statement q(db_,
                      "SELECT p.study, p.code, s.id, s.started, s.finished, "
                      "(SELECT count(*) FROM trials t WHERE t.session = s.id), "
                      "(SELECT count(*) FROM responses r WHERE r.session = s.id), " +
                          std::string(autopilot_column()) +
                          " FROM sessions s JOIN participants p ON p.id = s.participant ORDER BY s.id");
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
    row.autopilot = q.column_int64(7) != 0;
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
                      "t.block_type, e.trial_index, " + std::string(autopilot_column()) +
                          ", e.kind, e.stimulus, t.stimuli, t.stimulus_hashes, coalesce(e.detail, ''), e.timestamp_ms "
                          "FROM events e JOIN trials t USING (session, block_index, trial_index) "
                          "JOIN sessions s ON s.id = e.session JOIN participants p ON p.id = s.participant "
                          "JOIN studies st ON st.id = p.study ORDER BY e.session, e.id");
  std::vector<EventRow> rows;
  while (q.step()) {
    EventRow row;
    read_context(q, row);
    row.kind = q.column_text(10);
    row.stimulus = q.column_text(11);
    // The hash of the played stimulus, looked up among the trial's stimuli (a slider or staircase
    // variant carries its own hash in the detail instead).
    const auto names = nlohmann::json::parse(q.column_text(12));
    const auto hashes = nlohmann::json::parse(q.column_text(13));
    for (std::size_t i = 0; i < names.size() && i < hashes.size(); ++i)
      if (names[i] == row.stimulus) row.stimulus_hash = hashes[i].get<std::string>();
    row.detail_json = q.column_text(14);
    row.timestamp_ms = q.column_int64(15);
    rows.push_back(std::move(row));
  }
  check_complete(path(), "events", count("events"), rows.size());
  return rows;
}

std::vector<TrialRow> ResultsStore::trial_rows() const {
  sqlite::Statement q(db_,
                      "SELECT p.study, p.id, p.code, st.export_personal, t.session, t.block_index, t.block_id, "
                      "t.block_type, t.trial_index, " + std::string(autopilot_column()) +
                          ", t.stimuli, t.stimulus_hashes "
                          "FROM trials t JOIN sessions s ON s.id = t.session JOIN participants p ON p.id = s.participant "
                          "JOIN studies st ON st.id = p.study ORDER BY t.session, t.block_index, t.trial_index");
  std::vector<TrialRow> rows;
  while (q.step()) {
    TrialRow row;
    read_context(q, row);
    row.stimuli_json = q.column_text(10);
    row.hashes_json = q.column_text(11);
    rows.push_back(std::move(row));
  }
  check_complete(path(), "trials", count("trials"), rows.size());
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
                      "t.block_type, r.trial_index, " + std::string(autopilot_column()) +
                          ", t.stimuli, r.value, r.rt_ms, r.plays, r.timestamp "
                          "FROM responses r JOIN trials t USING (session, block_index, trial_index) "
                          "JOIN sessions s ON s.id = r.session JOIN participants p ON p.id = s.participant "
                          "JOIN studies st ON st.id = p.study ORDER BY r.session, r.block_index, r.trial_index");
  std::vector<ResponseRow> rows;
  while (q.step()) {
    ResponseRow row;
    read_context(q, row);
    row.stimuli_json = q.column_text(10);
    row.value_json = q.column_text(11);
    row.rt_ms = q.column_double(12);
    row.plays = int(q.column_int64(13));
    row.timestamp_ms = q.column_int64(14);
    rows.push_back(std::move(row));
  }
  check_complete(path(), "responses", count("responses"), rows.size());
  return rows;
}

std::int64_t ResultsStore::count(const std::string& table) const {
  static const std::array<std::string, 7> known{"studies",   "participants", "sessions", "trials",
                                                "responses", "events",       "leases"};
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
