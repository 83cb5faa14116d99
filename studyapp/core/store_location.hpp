// Where a results store lives: a file path (SQLite, the embedded default) or a PostgreSQL URI
// (postgresql://user@host:port/dbname or postgres://...), the one string every entry point takes as --db.
#pragma once
#include <string>
#include <string_view>

namespace ms {

bool is_postgres_uri(std::string_view location);

// The location as it may be printed or logged: a URI's password (user:PASSWORD@host) cut out.
std::string location_without_password(const std::string& location);

// Whether the location already holds a results store (a non-empty file; a database with the schema),
// for callers that treat "nothing stored yet" as empty rather than as an error. Throws InputError
// naming the location when a server cannot be reached.
bool store_exists(const std::string& location);

}  // namespace ms
