// StoreConnection: what the results store needs from a database, so that one ResultsStore runs on
// SQLite (a file) and on PostgreSQL (a server) alike. SQL is written once, in the dialect both accept,
// with numbered parameters $1, $2, ... (a value never enters the SQL text); rows come back typed.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ms {

// 2: sessions.autopilot and the leases table (an SQLite version-1 file is migrated when opened for writing).
inline constexpr int kStoreSchemaVersion = 2;
inline constexpr int kStoreApplicationId = 0x4d535444;  // "MSTD": SQLite's application_id, PostgreSQL's table comment

// create_or_open: the store is created if missing; open_existing: refused if missing; read_only: never written.
enum class StoreMode { create_or_open, open_existing, read_only };

// One parameter or one cell: NULL, an integer, a real or a text.
class SqlValue {
 public:
  SqlValue(std::nullptr_t) {}
  SqlValue(int v) : v_(std::int64_t{v}) {}
  SqlValue(std::int64_t v) : v_(v) {}
  SqlValue(double v) : v_(v) {}
  SqlValue(std::string v) : v_(std::move(v)) {}
  SqlValue(std::string_view v) : v_(std::string(v)) {}
  SqlValue(const char* v) : v_(std::string(v)) {}

  bool is_null() const { return std::holds_alternative<std::monostate>(v_); }
  bool holds_text() const { return std::holds_alternative<std::string>(v_); }
  bool holds_real() const { return std::holds_alternative<double>(v_); }
  // A text cell (PostgreSQL answers in text) is converted on reading; NULL reads as 0 or "".
  std::int64_t int64() const;
  double real() const;
  std::string text() const;

 private:
  std::variant<std::monostate, std::int64_t, double, std::string> v_;
};

using SqlRow = std::vector<SqlValue>;
using SqlParams = std::vector<SqlValue>;

class StoreConnection {
 public:
  virtual ~StoreConnection() = default;

  // Runs one statement and returns all its rows. Throws StoreError naming the location.
  std::vector<SqlRow> query(std::string_view sql, const SqlParams& params = {}) { return run(sql, params); }
  // A write transaction. `serialize_key` names what concurrent openers must not race for (a study):
  // SQLite serialises every writer anyway (BEGIN IMMEDIATE); PostgreSQL takes a transaction-scoped
  // advisory lock on the key, so two processes opening one participant queue instead of racing.
  virtual void begin(std::string_view serialize_key = {}) = 0;
  void commit() { query("COMMIT"); }
  void rollback() noexcept {
    try {
      query("ROLLBACK");
    } catch (...) {  // a lost connection or file rolls back by itself; never throw here
    }
  }
  // Appended to a SELECT that reads a row the transaction will update: " FOR UPDATE" where row locks
  // exist (PostgreSQL); "" where the whole database is already locked for writing (SQLite).
  virtual const char* for_update() const = 0;
  // "ok" when the database's own check passes.
  virtual std::string integrity_check() = 0;
  // The location for messages: the file, or the URI without its password.
  virtual const std::string& location() const = 0;

 protected:
  virtual std::vector<SqlRow> run(std::string_view sql, const SqlParams& params) = 0;
};

// An opened and checked store: ours, not newer than this program, migrated when writable.
struct OpenedConnection {
  std::unique_ptr<StoreConnection> db;
  int schema_version = kStoreSchemaVersion;
};

// BEGIN ... COMMIT on a StoreConnection; rolls back if destroyed before commit() (e.g. by an exception).
class StoreTransaction {
 public:
  explicit StoreTransaction(StoreConnection& db, std::string_view serialize_key = {}) : db_(db) {
    db_.begin(serialize_key);
  }
  ~StoreTransaction() {
    if (!done_) db_.rollback();
  }
  StoreTransaction(const StoreTransaction&) = delete;
  StoreTransaction& operator=(const StoreTransaction&) = delete;
  void commit() {
    db_.commit();
    done_ = true;
  }

 private:
  StoreConnection& db_;
  bool done_ = false;
};

}  // namespace ms
