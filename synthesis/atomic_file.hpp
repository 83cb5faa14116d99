// Write-then-rename, so a failed or interrupted write never leaves a partial output file.
#pragma once
#include <functional>
#include <string>

namespace ms {

// Calls write(temp_path) for a temporary file beside `path`, then renames it onto `path`.
// On any exception the temporary is removed and the exception propagates; `path` is untouched.
void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write);

// Convenience for text/binary content held in memory.
void write_file_atomically(const std::string& path, const std::string& content);

// From now on SIGINT and SIGTERM first remove the temporaries of writes in progress, then end the
// process as the signal would have (programs call this once; a library never installs handlers).
void remove_temporaries_on_signals();

}  // namespace ms
