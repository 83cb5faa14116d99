// The PostgreSQL back end of the results store: one database (or the first schema of its search_path)
// shared by many booths and `serve` processes. The tables, columns and constraints are SQLite's; the
// schema is versioned in the same schema_version table, whose comment marks the database as ours.
// Every commit waits for the server's WAL flush (synchronous_commit=on).
#pragma once
#include <string>

#include "studyapp/core/store_connection.hpp"

namespace ms {

// Throws ms::InputError naming the URI (never its password) for a malformed URI, an unreachable
// server, a database of another application, a newer schema, or (open_existing, read_only) a database
// without a results store; such a database is never written to.
OpenedConnection open_postgres_store(const std::string& uri, StoreMode mode);

// Whether the database at `uri` holds a results store.
bool postgres_store_exists(const std::string& uri);

}  // namespace ms
