// ResultsStore: the store's rules (sessions, leases, one transaction per answer) and queries, once for
// both back ends; see results_store.hpp.
#include "studyapp/core/results_store.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <ctime>

#include "studyapp/core/postgres_store.hpp"
#include "studyapp/core/sqlite_store.hpp"
#include "studyapp/core/store_location.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

namespace {

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

// The export's three queries share their first ten columns (the TrialContext) and their joins: `key`
// is the alias of the table read, `from` that table joined to its trial `t`, `extra` its own columns.
std::string context_query(const std::string& key, const std::string& from, const char* autopilot,
                          const std::string& extra, const std::string& order) {
  return "SELECT p.study, p.id, p.code, st.export_personal, " + key + ".session, " + key + ".block_index, t.block_id, " +
         "t.block_type, " + key + ".trial_index, " + autopilot + ", " + extra + " FROM " + from +
         " JOIN sessions s ON s.id = " + key + ".session JOIN participants p ON p.id = s.participant "
         "JOIN studies st ON st.id = p.study ORDER BY " + order;
}

constexpr int kContextColumns = 10;

void read_context(const SqlRow& q, TrialContext& row) {
  row.study = q.at(0).text();
  row.participant = q.at(1).int64();
  row.participant_code = q.at(2).text();
  row.export_personal = q.at(3).int64() != 0;
  row.session = q.at(4).int64();
  row.block_index = int(q.at(5).int64());
  row.block_id = q.at(6).text();
  row.block_type = q.at(7).text();
  row.trial_index = int(q.at(8).int64());
  row.autopilot = q.at(9).int64() != 0;
}

std::optional<SessionRecord> read_session(const std::vector<SqlRow>& rows) {
  if (rows.empty()) return std::nullopt;
  const SqlRow& q = rows.front();
  SessionRecord r{q.at(0).int64(), q.at(1).int64(), q.at(2).int64(), std::nullopt,
                  static_cast<std::uint64_t>(q.at(4).int64()), q.at(5).int64() != 0};
  if (!q.at(3).is_null()) r.finished_ms = q.at(3).int64();
  return r;
}

OpenedConnection open_store(const std::string& location, StoreMode mode) {
  return is_postgres_uri(location) ? open_postgres_store(location, mode) : open_sqlite_store(location, mode);
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

ResultsStore::ResultsStore(const std::string& location, Mode mode) {
  OpenedConnection opened = open_store(location, mode);
  db_ = std::move(opened.db);
  schema_version_ = opened.schema_version;
  writable_ = mode != Mode::read_only;
}

const char* ResultsStore::autopilot_column() const { return schema_version_ >= 2 ? "s.autopilot" : "0"; }

void ResultsStore::add_study(const StudyRecord& study) {
  const auto found = db_->query("SELECT protocol_sha256 FROM studies WHERE id = $1", {study.id});
  if (!found.empty()) {
    const std::string stored = found.front().at(0).text();
    if (stored != study.protocol_sha256)
      throw InputError(SourceLocation{path(), 0, 0}, "study '" + study.id +
                                                         "' is already stored with a different protocol (sha256 " +
                                                         stored + ")");
    return;
  }
  db_->query("INSERT INTO studies(id, title, protocol_sha256, protocol_text, export_personal) VALUES ($1, $2, $3, $4, $5)",
             {study.id, study.title, study.protocol_sha256, study.protocol_text, study.export_personal ? 1 : 0});
}

std::int64_t ResultsStore::add_participant(const std::string& study_id, const std::string& code,
                                           std::int64_t created_ms) {
  return db_->query("INSERT INTO participants(study, code, created) VALUES ($1, $2, $3) RETURNING id",
                    {study_id, code, created_ms})
      .at(0).at(0).int64();
}

std::int64_t ResultsStore::start_session(std::int64_t participant, std::int64_t started_ms,
                                         std::uint64_t schedule_seed) {
  // Integers are signed 64-bit in both databases; the seed is stored bit for bit.
  return db_->query("INSERT INTO sessions(participant, started, schedule_seed) VALUES ($1, $2, $3) RETURNING id",
                    {participant, started_ms, static_cast<std::int64_t>(schedule_seed)})
      .at(0).at(0).int64();
}

void ResultsStore::finish_session(std::int64_t session, std::int64_t finished_ms) {
  db_->query("UPDATE sessions SET finished = $1 WHERE id = $2", {finished_ms, session});
}

void ResultsStore::insert_trials(std::int64_t session, const std::vector<TrialRecord>& trials) {
  for (const TrialRecord& t : trials)
    db_->query("INSERT INTO trials(session, block_index, block_id, block_type, trial_index, stimuli, "
               "stimulus_hashes) VALUES ($1, $2, $3, $4, $5, $6, $7)",
               {session, t.block_index, t.block_id, t.block_type, t.trial_index, json_array(t.stimuli),
                json_array(t.stimulus_hashes)});
}

void ResultsStore::record_trials(std::int64_t session, const std::vector<TrialRecord>& trials) {
  StoreTransaction tx(*db_);
  insert_trials(session, trials);
  tx.commit();
}

OpenedSession ResultsStore::open_session(const StudyRecord& study, const SessionRequest& r) {
  // Serialised per study: a second process opening the same participant waits here and then sees the
  // first one's participant, session and lease instead of racing it to the INSERTs.
  StoreTransaction tx(*db_, r.study_id);
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
    const auto lease = db_->query(
        std::string("SELECT host, pid, process_start, heartbeat_ms FROM leases WHERE session = $1") + db_->for_update(),
        {open->id});
    if (!lease.empty()) {
      const SqlRow& l = lease.front();
      const LeaseHolder holder{l.at(0).text(), l.at(1).int64(), l.at(2).text()};
      const std::int64_t heartbeat_ms = l.at(3).int64();
      if (!(holder == r.holder) && !lease_is_stale(holder, heartbeat_ms, r.now_ms))
        throw SessionInUse(SourceLocation{path(), 0, 0},
                           "participant '" + r.participant + "' is being run right now by " + describe(holder) +
                               " (session " + std::to_string(open->id) + ", last sign of life " +
                               std::to_string((r.now_ms - heartbeat_ms) / 1000) + " s ago); finish or close that run first");
    }
    out.session = open->id;
    out.resumed = true;
    if (r.autopilot) db_->query("UPDATE sessions SET autopilot = 1 WHERE id = $1", {out.session});
  } else {
    if (known && !r.new_session)
      if (const auto last = latest_session(out.participant); last && last->finished_ms) {
        const SqlRow n = db_->query("SELECT (SELECT count(*) FROM responses WHERE session = $1), "
                                    "(SELECT count(*) FROM trials WHERE session = $1)",
                                    {last->id})
                             .at(0);
        throw ParticipantFinished(SourceLocation{path(), 0, 0},
                                  r.participant + " finished this study on " + utc_date(*last->finished_ms) + " (" +
                                      n.at(0).text() + "/" + n.at(1).text() + " trials); use --new-session to run it again");
      }
    out.session = db_->query("INSERT INTO sessions(participant, started, schedule_seed, autopilot) "
                             "VALUES ($1, $2, $3, $4) RETURNING id",
                             {out.participant, r.now_ms, static_cast<std::int64_t>(r.schedule_seed), r.autopilot ? 1 : 0})
                      .at(0).at(0).int64();
    insert_trials(out.session, r.trials);
  }
  db_->query("INSERT INTO leases(session, host, pid, process_start, acquired_ms, heartbeat_ms) "
             "VALUES ($1, $2, $3, $4, $5, $5) ON CONFLICT(session) DO UPDATE SET host = $2, pid = $3, "
             "process_start = $4, acquired_ms = $5, heartbeat_ms = $5",
             {out.session, r.holder.host, r.holder.pid, r.holder.process_start, r.now_ms});
  tx.commit();
  return out;
}

// Inside a write transaction: refuses to write for a session whose lease another process holds (it
// took over a lease it judged stale), and renews the heartbeat of our own. The lease row stays locked
// until the transaction ends, so a takeover waits for an answer in flight and vice versa. Sessions
// never leased (stores written directly, e.g. by tools) are not checked.
void ResultsStore::check_lease(std::int64_t session, const LeaseHolder& holder, std::int64_t now_ms) {
  const auto lease = db_->query(
      std::string("SELECT host, pid, process_start FROM leases WHERE session = $1") + db_->for_update(), {session});
  if (lease.empty()) return;
  const LeaseHolder owner{lease.front().at(0).text(), lease.front().at(1).int64(), lease.front().at(2).text()};
  if (!(owner == holder))
    throw SessionInUse(SourceLocation{path(), 0, 0}, "session " + std::to_string(session) + " is now run by " +
                                                         describe(owner) + "; this run stops without storing more");
  db_->query("UPDATE leases SET heartbeat_ms = $1 WHERE session = $2", {now_ms, session});
}

void ResultsStore::renew_lease(std::int64_t session, const LeaseHolder& holder, std::int64_t now_ms) {
  StoreTransaction tx(*db_);
  check_lease(session, holder, now_ms);
  tx.commit();
}

void ResultsStore::release_lease(std::int64_t session, const LeaseHolder& holder) {
  db_->query("DELETE FROM leases WHERE session = $1 AND host = $2 AND pid = $3 AND process_start = $4",
             {session, holder.host, holder.pid, holder.process_start});
}

void ResultsStore::write_in_session(std::int64_t session, std::int64_t now_ms, const std::function<void()>& write) {
  if (!writable_) throw StoreError(path() + ": opened read-only", false);
  // One transaction per write; COMMIT returns only once it is on disk (SQLite: synchronous=FULL;
  // PostgreSQL: synchronous_commit=on).
  StoreTransaction tx(*db_);
  check_lease(session, me_, now_ms);
  write();
  tx.commit();
}

void ResultsStore::record_response(std::int64_t session, const ResponseRecord& r) {
  write_in_session(session, r.timestamp_ms, [&] {
    try {
      db_->query("INSERT INTO responses(session, block_index, trial_index, value, rt_ms, plays, timestamp) "
                 "VALUES ($1, $2, $3, $4, $5, $6, $7)",
                 {session, r.trial.block_index, r.trial.trial_index, r.value_json, r.rt_ms, r.plays, r.timestamp_ms});
    } catch (const StoreError& e) {
      if (!e.refused()) throw;
      throw StoreError(path() + ": cannot record response to session " + std::to_string(session) + " block " +
                           std::to_string(r.trial.block_index) + " trial " + std::to_string(r.trial.trial_index) +
                           " (already answered, not scheduled, or value not JSON): " + e.what(),
                       true);
    }
  });
}

void ResultsStore::record_event(std::int64_t session, const PlaybackEvent& e) {
  write_in_session(session, e.timestamp_ms, [&] {
    db_->query("INSERT INTO events(session, block_index, trial_index, kind, stimulus, timestamp_ms, detail) "
               "VALUES ($1, $2, $3, $4, $5, $6, $7)",
               {session, e.trial.block_index, e.trial.trial_index, to_string(e.kind), e.stimulus, e.timestamp_ms,
                e.detail_json.empty() ? SqlValue(nullptr) : SqlValue(e.detail_json)});
  });
}

std::optional<TrialPosition> ResultsStore::first_unanswered_trial(std::int64_t session) const {
  const auto rows = db_->query(
      "SELECT t.block_index, t.trial_index FROM trials t LEFT JOIN responses r "
      "ON r.session = t.session AND r.block_index = t.block_index AND r.trial_index = t.trial_index "
      "WHERE t.session = $1 AND r.id IS NULL ORDER BY t.block_index, t.trial_index LIMIT 1",
      {session});
  if (rows.empty()) return std::nullopt;
  return TrialPosition{int(rows.front().at(0).int64()), int(rows.front().at(1).int64())};
}

std::optional<std::int64_t> ResultsStore::find_participant(const std::string& study_id,
                                                           const std::string& code) const {
  const auto rows = db_->query("SELECT id FROM participants WHERE study = $1 AND code = $2", {study_id, code});
  if (rows.empty()) return std::nullopt;
  return rows.front().at(0).int64();
}

std::vector<std::string> ResultsStore::participant_codes(const std::string& study_id) const {
  std::vector<std::string> out;
  for (const SqlRow& r : db_->query("SELECT code FROM participants WHERE study = $1 ORDER BY id", {study_id}))
    out.push_back(r.at(0).text());
  return out;
}

std::optional<SessionRecord> ResultsStore::unfinished_session(std::int64_t participant) const {
  return read_session(db_->query("SELECT s.id, s.participant, s.started, s.finished, s.schedule_seed, " +
                                     std::string(autopilot_column()) +
                                     " FROM sessions s WHERE s.participant = $1 AND s.finished IS NULL "
                                     "ORDER BY s.id DESC LIMIT 1",
                                 {participant}));
}

std::optional<SessionRecord> ResultsStore::latest_session(std::int64_t participant) const {
  return read_session(db_->query("SELECT s.id, s.participant, s.started, s.finished, s.schedule_seed, " +
                                     std::string(autopilot_column()) +
                                     " FROM sessions s WHERE s.participant = $1 ORDER BY s.id DESC LIMIT 1",
                                 {participant}));
}

std::vector<SessionSummary> ResultsStore::session_summaries() const {
  std::vector<SessionSummary> out;
  for (const SqlRow& q : db_->query("SELECT p.study, p.code, s.id, s.started, s.finished, "
                                    "(SELECT count(*) FROM trials t WHERE t.session = s.id), "
                                    "(SELECT count(*) FROM responses r WHERE r.session = s.id), " +
                                    std::string(autopilot_column()) +
                                    " FROM sessions s JOIN participants p ON p.id = s.participant ORDER BY s.id")) {
    SessionSummary row;
    row.study = q.at(0).text();
    row.participant_code = q.at(1).text();
    row.session = q.at(2).int64();
    row.started_ms = q.at(3).int64();
    if (!q.at(4).is_null()) row.finished_ms = q.at(4).int64();
    row.trials = q.at(5).int64();
    row.responses = q.at(6).int64();
    row.autopilot = q.at(7).int64() != 0;
    out.push_back(std::move(row));
  }
  return out;
}

std::vector<TrialPosition> ResultsStore::answered_trials(std::int64_t session) const {
  std::vector<TrialPosition> out;
  for (const SqlRow& r : db_->query("SELECT block_index, trial_index FROM responses WHERE session = $1", {session}))
    out.push_back({int(r.at(0).int64()), int(r.at(1).int64())});
  return out;
}

std::vector<PlaybackEvent> ResultsStore::events(std::int64_t session, TrialPosition trial) const {
  std::vector<PlaybackEvent> out;
  for (const SqlRow& q : db_->query("SELECT kind, stimulus, timestamp_ms, coalesce(detail, '') FROM events "
                                    "WHERE session = $1 AND block_index = $2 AND trial_index = $3 ORDER BY id",
                                    {session, trial.block_index, trial.trial_index})) {
    const std::string kind = q.at(0).text();
    PlaybackEvent e;
    e.trial = trial;
    e.kind = kind == "stop" ? EventKind::stop
             : kind == "switch" ? EventKind::switch_to
             : kind == "step"   ? EventKind::step
                                : EventKind::play;
    e.stimulus = q.at(1).text();
    e.timestamp_ms = q.at(2).int64();
    e.detail_json = q.at(3).text();
    out.push_back(std::move(e));
  }
  return out;
}

template <typename Row, typename Fill>
std::vector<Row> ResultsStore::context_rows(const char* table, const std::string& sql, Fill fill) const {
  std::vector<Row> rows;
  for (const SqlRow& q : db_->query(sql)) {
    Row row;
    read_context(q, row);
    fill(q, row);
    rows.push_back(std::move(row));
  }
  check_complete(path(), table, count(table), rows.size());
  return rows;
}

std::vector<EventRow> ResultsStore::event_rows() const {
  return context_rows<EventRow>(
      "events",
      context_query("e", "events e JOIN trials t USING (session, block_index, trial_index)", autopilot_column(),
                    "e.kind, e.stimulus, t.stimuli, t.stimulus_hashes, coalesce(e.detail, ''), e.timestamp_ms",
                    "e.session, e.id"),
      [](const SqlRow& q, EventRow& row) {
        constexpr int c = kContextColumns;
        row.kind = q.at(c).text();
        row.stimulus = q.at(c + 1).text();
        // The hash of the played stimulus, looked up among the trial's stimuli (a slider or staircase
        // variant carries its own hash in the detail instead).
        const auto names = nlohmann::json::parse(q.at(c + 2).text());
        const auto hashes = nlohmann::json::parse(q.at(c + 3).text());
        for (std::size_t i = 0; i < names.size() && i < hashes.size(); ++i)
          if (names[i] == row.stimulus) row.stimulus_hash = hashes[i].get<std::string>();
        row.detail_json = q.at(c + 4).text();
        row.timestamp_ms = q.at(c + 5).int64();
      });
}

std::vector<TrialRow> ResultsStore::trial_rows() const {
  return context_rows<TrialRow>("trials",
                                context_query("t", "trials t", autopilot_column(), "t.stimuli, t.stimulus_hashes",
                                              "t.session, t.block_index, t.trial_index"),
                                [](const SqlRow& q, TrialRow& row) {
                                  row.stimuli_json = q.at(kContextColumns).text();
                                  row.hashes_json = q.at(kContextColumns + 1).text();
                                });
}

std::vector<ResponseRow> ResultsStore::response_rows() const {
  return context_rows<ResponseRow>(
      "responses",
      context_query("r", "responses r JOIN trials t USING (session, block_index, trial_index)", autopilot_column(),
                    "t.stimuli, r.value, r.rt_ms, r.plays, r.timestamp", "r.session, r.block_index, r.trial_index"),
      [](const SqlRow& q, ResponseRow& row) {
        constexpr int c = kContextColumns;
        row.stimuli_json = q.at(c).text();
        row.value_json = q.at(c + 1).text();
        row.rt_ms = q.at(c + 2).real();
        row.plays = int(q.at(c + 3).int64());
        row.timestamp_ms = q.at(c + 4).int64();
      });
}

std::vector<StudyRecord> ResultsStore::studies() const {
  std::vector<StudyRecord> out;
  for (const SqlRow& q :
       db_->query("SELECT id, title, protocol_sha256, protocol_text, export_personal FROM studies ORDER BY id"))
    out.push_back({q.at(0).text(), q.at(1).text(), q.at(2).text(), q.at(3).text(), q.at(4).int64() != 0});
  return out;
}

std::optional<ResponseRecord> ResultsStore::response(std::int64_t session, TrialPosition trial) const {
  const auto rows = db_->query("SELECT value, rt_ms, plays, timestamp FROM responses "
                               "WHERE session = $1 AND block_index = $2 AND trial_index = $3",
                               {session, trial.block_index, trial.trial_index});
  if (rows.empty()) return std::nullopt;
  const SqlRow& q = rows.front();
  return ResponseRecord{trial, q.at(0).text(), q.at(1).real(), int(q.at(2).int64()), q.at(3).int64()};
}

std::int64_t ResultsStore::count(const std::string& table) const {
  static const std::array<std::string, 7> known{"studies",   "participants", "sessions", "trials",
                                                "responses", "events",       "leases"};
  if (std::find(known.begin(), known.end(), table) == known.end())
    throw std::invalid_argument("ResultsStore::count: unknown table '" + table + "'");
  return db_->query("SELECT count(*) FROM " + table).at(0).at(0).int64();  // a name from the list above
}

std::string ResultsStore::integrity_check() const { return db_->integrity_check(); }

}  // namespace ms
