// The SQLite back end of the results store: one file, created atomically (schema built in a temporary
// file, then linked into place), checked on every open (a damaged or foreign file is refused by name
// and never written to), WAL with synchronous=FULL, migrated from version 1 when opened for writing.
#pragma once
#include <string>

#include "studyapp/core/store_connection.hpp"

namespace ms {

// Throws ms::InputError naming `path` if the file is not a ModalStudy database, is damaged
// (PRAGMA quick_check; integrity_check when read_only) or has a newer schema. open_existing/read_only
// also refuse a missing file; create_or_open treats an empty file (left by a creation that was killed
// or ran out of disk) as missing.
OpenedConnection open_sqlite_store(const std::string& path, StoreMode mode);

}  // namespace ms
