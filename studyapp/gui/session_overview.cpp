// session_overview: one read-only query over the results store's sessions, trials and responses.
#include "studyapp/gui/session_overview.hpp"

#include <sqlite3.h>

#include "studyapp/core/results_store.hpp"
#include "studyapp/core/sqlite_handle.hpp"

namespace ms::gui {

std::vector<SessionSummary> session_overview(const std::string& db_path) {
  { ResultsStore check(db_path, ResultsStore::Mode::read_only); }  // refuses files that are not ours, by name
  sqlite::Database db(db_path, SQLITE_OPEN_READONLY);
  sqlite::Statement q(db, R"sql(
    SELECT p.study, p.code, s.id, s.started, s.finished,
           (SELECT count(*) FROM responses r WHERE r.session = s.id),
           (SELECT count(*) FROM trials t WHERE t.session = s.id)
    FROM sessions s JOIN participants p ON p.id = s.participant ORDER BY s.id)sql");
  std::vector<SessionSummary> out;
  while (q.step()) {
    SessionSummary s;
    s.study = q.column_text(0);
    s.participant = q.column_text(1);
    s.session = q.column_int64(2);
    s.started_ms = q.column_int64(3);
    if (!q.is_null(4)) s.finished_ms = q.column_int64(4);
    s.answered = q.column_int64(5);
    s.scheduled = q.column_int64(6);
    out.push_back(s);
  }
  return out;
}

}  // namespace ms::gui
