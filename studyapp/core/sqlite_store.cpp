// The SQLite back end of the results store: one file, created atomically, checked before use; see
// sqlite_store.hpp.
#include "studyapp/core/sqlite_store.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sqlite3.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <fstream>

#include "studyapp/core/sqlite_handle.hpp"
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
// loses the link; both then open the one file. Threads of one process take turns, since the temporary
// file is named by the process (so that one left by a killed process can be told and removed).
void create_atomically(const std::string& path) {
  static std::mutex creating;
  const std::lock_guard lock(creating);
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
    db.exec("PRAGMA application_id=" + std::to_string(kStoreApplicationId));
    db.exec("INSERT INTO schema_version(version) VALUES (" + std::to_string(kStoreSchemaVersion) + ")");
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
    db.exec("PRAGMA busy_timeout=5000; PRAGMA query_only=1");  // another connection may be opening it
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


// SQL of store_connection.hpp's dialect ($1, $2, ...) in SQLite's spelling of numbered parameters (?1, ?2, ...).
std::string numbered_parameters(std::string_view sql) {
  std::string out(sql);
  for (std::size_t i = 0; i + 1 < out.size(); ++i)
    if (out[i] == '$' && out[i + 1] >= '0' && out[i + 1] <= '9') out[i] = '?';
  return out;
}

class SqliteConnection final : public StoreConnection {
 public:
  explicit SqliteConnection(sqlite::Database db) : db_(std::move(db)) {}

  std::vector<SqlRow> run(std::string_view sql, const SqlParams& params) override {
    sqlite::Statement q(db_, numbered_parameters(sql));
    for (std::size_t i = 0; i < params.size(); ++i) {
      const int index = int(i) + 1;
      const SqlValue& v = params[i];
      if (v.is_null()) q.bind_null(index);
      else if (v.holds_text()) q.bind(index, v.text());
      else if (v.holds_real()) q.bind(index, v.real());
      else q.bind(index, v.int64());
    }
    std::vector<SqlRow> rows;
    while (q.step()) {
      SqlRow row;
      for (int c = 0; c < q.column_count(); ++c) {
        switch (q.column_type(c)) {
          case SQLITE_NULL: row.emplace_back(nullptr); break;
          case SQLITE_INTEGER: row.emplace_back(q.column_int64(c)); break;
          case SQLITE_FLOAT: row.emplace_back(q.column_double(c)); break;
          default: row.emplace_back(q.column_text(c));
        }
      }
      rows.push_back(std::move(row));
    }
    return rows;
  }

  // BEGIN IMMEDIATE: the write lock at once, so a second writer waits (busy_timeout) instead of
  // failing later at its first write; it serialises every key.
  void begin(std::string_view) override { db_.exec("BEGIN IMMEDIATE"); }
  const char* for_update() const override { return ""; }

  std::string integrity_check() override {
    std::string out;
    for (const SqlRow& r : query("PRAGMA integrity_check", {})) out += (out.empty() ? "" : "; ") + r.at(0).text();
    return out;
  }
  const std::string& location() const override { return db_.path(); }

  sqlite::Database& raw() { return db_; }

 private:
  sqlite::Database db_;
};

}  // namespace

OpenedConnection open_sqlite_store(const std::string& path, StoreMode mode) {
  if (mode == StoreMode::create_or_open) create_atomically(path);
  check_header(path);
  if (mode != StoreMode::read_only && access(folder_of(path).c_str(), W_OK) != 0)
    throw InputError(SourceLocation{path, 0, 0},
                     "cannot write to the results database: SQLite keeps its write-ahead log (" +
                         fs::path(path).filename().string() + "-wal, -shm) beside it and has no permission "
                         "to write in folder " + folder_of(path));
  check_intact(path, mode == StoreMode::read_only);
  const int flags = mode == StoreMode::read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE;
  std::unique_ptr<SqliteConnection> conn;
  try {
    conn = std::make_unique<SqliteConnection>(sqlite::Database(path, flags));
  } catch (const sqlite::Error& e) {
    throw InputError(SourceLocation{path, 0, 0}, "cannot open results database: " + std::string(e.what()));
  }
  sqlite::Database& db = conn->raw();
  db.exec("PRAGMA busy_timeout=5000; PRAGMA foreign_keys=ON");
  // Only reads until the file is known to be ours and of a version this program understands.
  if (conn->query("PRAGMA application_id").at(0).at(0).int64() != kStoreApplicationId)
    not_ours(path, "another application's SQLite file");
  const std::int64_t v = conn->query("SELECT max(version) FROM schema_version").at(0).at(0).int64();
  if (v > kStoreSchemaVersion)
    throw InputError(SourceLocation{path, 0, 0}, "schema version " + std::to_string(v) +
                                                     " is newer than this program supports (" +
                                                     std::to_string(kStoreSchemaVersion) + "); update ModalStudy");
  OpenedConnection out;
  out.schema_version = int(v);
  if (mode != StoreMode::read_only) {
    // WAL: a commit appends to the log, readers (an export during a session) never block the writer.
    // synchronous=FULL: WAL with NORMAL survives a program crash but may lose the last commits on
    // power loss; FULL fsyncs the log at every COMMIT, so an answer acknowledged to the participant
    // is on disk before the next trial is shown, at ~1 fsync per response (see bench_results_store).
    db.exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL");
    if (out.schema_version < 2) {
      StoreTransaction tx(*conn);
      // another process may have migrated meanwhile
      if (conn->query("SELECT max(version) FROM schema_version").at(0).at(0).int64() < 2) {
        db.exec(kMigrateTo2);
        db.exec(kLeaseSchema);
        db.exec("INSERT INTO schema_version(version) VALUES (2)");
      }
      tx.commit();
      out.schema_version = 2;
    }
  }
  out.db = std::move(conn);
  return out;
}

}  // namespace ms
