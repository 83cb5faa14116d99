// RAII wrappers for libpq (PGconn*, PGresult*) with errors turned into exceptions that name the
// server by its URI without the password. Used by the PostgreSQL back end of the results store.
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "studyapp/core/store_error.hpp"

struct pg_conn;
struct pg_result;

namespace ms::pg {

// A failure reported by the server or by libpq; sqlstate() is the five-character SQLSTATE ("" for a
// connection failure). Constraint violations (class 23) and invalid values (class 22) are refusals.
class Error : public StoreError {
 public:
  Error(const std::string& message, std::string sqlstate);
  const std::string& sqlstate() const { return sqlstate_; }

 private:
  std::string sqlstate_;
};

// "postgresql://user@host:port/dbname" (the password and other parameters left out), for messages.
// Throws InputError naming the URI (without its password) when libpq cannot parse it.
std::string display_uri(const std::string& uri);

// One query's result; cells are text or NULL.
class Result {
 public:
  explicit Result(pg_result* r) : r_(r) {}
  ~Result();
  Result(const Result&) = delete;
  Result& operator=(const Result&) = delete;
  Result(Result&& o) noexcept : r_(o.r_) { o.r_ = nullptr; }
  int rows() const;
  int columns() const;
  bool is_null(int row, int column) const;
  std::string text(int row, int column) const;

 private:
  pg_result* r_;
};

class Connection {
 public:
  // `uri` as libpq takes it; refused (InputError naming the display URI) if malformed or unreachable.
  explicit Connection(const std::string& uri);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  // PQexecParams with every parameter as text (nullptr = NULL); throws Error unless the command succeeded.
  Result exec(std::string_view sql, const std::vector<const char*>& params = {});
  const std::string& location() const { return location_; }

 private:
  pg_conn* conn_ = nullptr;
  std::string location_;
};

}  // namespace ms::pg
