// Export of a results database to tidy data: responses.csv (one row per response, RFC 4180) and
// study.json (study metadata and counts), both written atomically; read by `modalstudy stats`.
#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"
#include "studyapp/core/results_store.hpp"

namespace ms {

struct ExportSummary {
  std::string csv_path, json_path;
  std::size_t responses = 0;
  std::vector<std::string> tables;  // per-type tidy tables written (e.g. "mushra.csv")
  std::vector<std::string> notices; // stored answers left out of the typed tables (see tidy_tables)
};

// Reads `db_path` (read-only; never modified) and writes out_dir/responses.csv, study.json, trials.csv
// (stimulus recipe hashes), events.csv (play/stop/switch/step) and one tidy table per block type.
// Throws ms::InputError naming the file for a missing file or one that is not a ModalStudy database;
// then nothing is written. out_dir is created if missing.
ExportSummary export_results(const std::string& db_path, const std::string& out_dir);

// The protocols stored with the studies of `store`, by study id; a stored protocol this version cannot
// read is left out (its tables then get empty truth and factor cells).
std::map<std::string, Protocol> stored_protocols(const ResultsStore& store);

// Unix milliseconds as ISO 8601 UTC with milliseconds, e.g. 2023-11-14T22:13:20.000Z.
std::string iso8601_utc(std::int64_t unix_ms);

}  // namespace ms
