// RAII wrappers for the SQLite C API (sqlite3*, sqlite3_stmt*) with errors turned into exceptions.
// Used by the results store and the export; callers never see a raw handle's lifetime.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "studyapp/core/store_error.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace ms::sqlite {

// A failure inside SQLite (I/O, constraint, misuse); what() names the database file.
class Error : public StoreError {
 public:
  Error(const std::string& message, int code);
  int code() const { return code_; }  // primary SQLite result code (e.g. SQLITE_CONSTRAINT)

 private:
  int code_;
};

class Database {
 public:
  // flags: SQLITE_OPEN_* (the caller decides whether the file may be created).
  Database(const std::string& path, int flags);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  Database(Database&& other) noexcept;
  Database& operator=(Database&& other) noexcept;

  void exec(const std::string& sql);  // one or more statements without results
  sqlite3* get() const { return db_; }
  const std::string& path() const { return path_; }
  std::int64_t last_insert_rowid() const;
  [[noreturn]] void fail(const std::string& what, int code) const;

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
};

// A prepared statement; reset() makes it reusable (binding indices are 1-based, columns 0-based).
class Statement {
 public:
  Statement(const Database& db, std::string_view sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, std::int64_t{value}); }
  Statement& bind(int index, double value);
  Statement& bind(int index, std::string_view text);
  Statement& bind_null(int index);

  bool step();  // true: a row is available; false: done. Throws Error otherwise.
  void run();   // step() to completion, then reset()
  void reset();

  int parameter_count() const;
  int column_count() const;
  int column_type(int column) const;  // SQLITE_INTEGER, SQLITE_FLOAT, SQLITE_TEXT, SQLITE_BLOB, SQLITE_NULL
  bool is_null(int column) const;
  std::int64_t column_int64(int column) const;
  double column_double(int column) const;
  std::string column_text(int column) const;

 private:
  const Database* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

// BEGIN IMMEDIATE ... COMMIT; rolls back if destroyed before commit() (e.g. by an exception).
class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

 private:
  Database& db_;
  bool done_ = false;
};

}  // namespace ms::sqlite
