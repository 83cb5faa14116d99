// RAII wrappers for libpq; see postgres_handle.hpp.
#include "studyapp/core/postgres_handle.hpp"

#include <libpq-fe.h>

#include "studyapp/core/store_location.hpp"
#include "synthesis/input_error.hpp"

namespace ms::pg {

namespace {

// libpq's messages span lines ("...failed: Connection refused\n\tIs the server running..."): one line.
std::string one_line(std::string text) {
  std::string out;
  bool space = false;
  for (char c : text) {
    if (c == '\n' || c == '\t' || c == '\r' || c == ' ') {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    out += c;
    space = false;
  }
  return out;
}

void ignore_notice(void*, const char*) {}  // NOTICEs (e.g. from DDL) are not the user's business

}  // namespace

Error::Error(const std::string& message, std::string sqlstate)
    : StoreError(message, sqlstate.rfind("23", 0) == 0 || sqlstate.rfind("22", 0) == 0),
      sqlstate_(std::move(sqlstate)) {}

std::string display_uri(const std::string& uri) {
  char* err = nullptr;
  PQconninfoOption* opts = PQconninfoParse(uri.c_str(), &err);
  if (!opts) {
    std::string why = err ? one_line(err) : "out of memory";
    PQfreemem(err);
    throw InputError(SourceLocation{location_without_password(uri), 0, 0},
                     "not a valid PostgreSQL URI (" + why + "); expected postgresql://user@host:port/dbname");
  }
  std::string user, host, port, dbname;
  for (const PQconninfoOption* o = opts; o->keyword; ++o) {
    if (!o->val) continue;
    const std::string k = o->keyword;
    if (k == "user") user = o->val;
    else if (k == "host" || (k == "hostaddr" && host.empty())) host = o->val;
    else if (k == "port") port = o->val;
    else if (k == "dbname") dbname = o->val;
  }
  PQconninfoFree(opts);
  return "postgresql://" + (user.empty() ? "" : user + "@") + host + (port.empty() ? "" : ":" + port) + "/" + dbname;
}

Result::~Result() { PQclear(r_); }
int Result::rows() const { return PQntuples(r_); }
int Result::columns() const { return PQnfields(r_); }
bool Result::is_null(int row, int column) const { return PQgetisnull(r_, row, column) != 0; }
std::string Result::text(int row, int column) const {
  return std::string(PQgetvalue(r_, row, column), std::size_t(PQgetlength(r_, row, column)));
}

Connection::Connection(const std::string& uri) : location_(display_uri(uri)) {
  // The URI's own settings override these defaults (later keywords win; dbname is expanded last).
  const char* keywords[] = {"connect_timeout", "application_name", "dbname", nullptr};
  const char* values[] = {"10", "modalstudy", uri.c_str(), nullptr};
  conn_ = PQconnectdbParams(keywords, values, 1);
  if (!conn_ || PQstatus(conn_) != CONNECTION_OK) {
    const std::string why = conn_ ? one_line(PQerrorMessage(conn_)) : "out of memory";
    PQfinish(conn_);
    conn_ = nullptr;
    throw InputError(SourceLocation{location_, 0, 0}, "cannot connect to the PostgreSQL server: " + why);
  }
  PQsetNoticeProcessor(conn_, ignore_notice, nullptr);
}

Connection::~Connection() { PQfinish(conn_); }

Result Connection::exec(std::string_view sql, const std::vector<const char*>& params) {
  const std::string text(sql);
  PGresult* r = params.empty() ? PQexec(conn_, text.c_str())
                               : PQexecParams(conn_, text.c_str(), int(params.size()), nullptr, params.data(), nullptr,
                                              nullptr, 0);
  Result result(r);
  const ExecStatusType status = r ? PQresultStatus(r) : PGRES_FATAL_ERROR;
  if (status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK) return result;
  const char* state = r ? PQresultErrorField(r, PG_DIAG_SQLSTATE) : nullptr;
  const std::string why = one_line(r ? PQresultErrorMessage(r) : PQerrorMessage(conn_));
  throw Error(location_ + ": " + (why.empty() ? one_line(PQerrorMessage(conn_)) : why), state ? state : "");
}

}  // namespace ms::pg
