// Tidy export of a results database; see export.hpp.
#include "studyapp/core/export.hpp"

#include <nlohmann/json.hpp>

#include <ctime>
#include <filesystem>
#include <map>

#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/results_store.hpp"
#include "studyapp/core/store_location.hpp"
#include "studyapp/core/tidy_tables.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/csv.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

namespace {

// Single stimulus -> its name (so `stats confusion --truth stimuli` reads labels directly);
// several -> names joined by ';' in presentation order.
std::string stimuli_cell(const std::string& json_text) {
  const auto j = nlohmann::json::parse(json_text);
  std::string out;
  for (const auto& s : j) out += (out.empty() ? "" : ";") + s.get<std::string>();
  return out;
}

// A JSON string answer becomes its plain text ("metal", not "\"metal\""); numbers and structured
// answers (MUSHRA ratings per condition) stay compact JSON.
std::string response_cell(const std::string& json_text) {
  const auto j = nlohmann::json::parse(json_text);
  return j.is_string() ? j.get<std::string>() : j.dump();
}

std::string number_cell(double v) {
  nlohmann::json j = v;  // shortest round-trip representation, as JSON prints it
  return j.dump();
}

}  // namespace

std::map<std::string, Protocol> stored_protocols(const ResultsStore& store) {
  std::map<std::string, Protocol> protocols;
  for (const StudyRecord& s : store.studies()) {
    try {
      protocols.emplace(s.id, parse_protocol(s.protocol_text, s.id + " (stored protocol)", "."));
    } catch (const InputError&) {
      // A protocol this version cannot read.
    }
  }
  return protocols;
}

std::string iso8601_utc(std::int64_t unix_ms) {
  std::int64_t secs = unix_ms / 1000, ms = unix_ms % 1000;
  if (ms < 0) {
    ms += 1000;
    --secs;
  }
  const std::time_t t = static_cast<std::time_t>(secs);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[40];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  char frac[8];
  std::snprintf(frac, sizeof frac, ".%03dZ", int(ms));
  return std::string(buf) + frac;
}

ExportSummary export_results(const std::string& db_path, const std::string& out_dir) {
  // Everything is read and formatted in memory first: a bad input leaves no file behind.
  const ResultsStore store(db_path, ResultsStore::Mode::read_only);
  const auto rows = store.response_rows();

  const std::vector<std::string> columns{"study", "participant", "session", "autopilot", "block", "block_type",
                                         "trial", "stimuli", "response", "rt_ms", "plays", "timestamp"};
  std::string csv = csv::line(columns);
  for (const ResponseRow& r : rows) {
    const std::string participant = exported_participant(r.participant_code, r.participant, r.export_personal);
    const std::string cells[] = {r.study,
                                 participant,
                                 std::to_string(r.session),
                                 r.autopilot ? "1" : "0",
                                 r.block_id,
                                 r.block_type,
                                 std::to_string(r.trial_index),
                                 stimuli_cell(r.stimuli_json),
                                 response_cell(r.value_json),
                                 number_cell(r.rt_ms),
                                 std::to_string(r.plays),
                                 iso8601_utc(r.timestamp_ms)};
    csv += csv::line({std::begin(cells), std::end(cells)});
  }

  // The schedule with the recipe hash of every stimulus, and every play/stop/switch/step event.
  std::string trials_csv = csv::line({"study", "participant", "session", "block", "block_type", "trial", "stimuli",
                                     "stimulus_hashes"});
  for (const TrialRow& t : store.trial_rows()) {
    std::string hashes;
    for (const auto& h : nlohmann::json::parse(t.hashes_json)) hashes += (hashes.empty() ? "" : ";") + h.get<std::string>();
    trials_csv += csv::line({t.study, exported_participant(t.participant_code, t.participant, t.export_personal),
                            std::to_string(t.session), t.block_id, t.block_type, std::to_string(t.trial_index),
                            stimuli_cell(t.stimuli_json), hashes});
  }
  std::string events_csv = csv::line({"study", "participant", "session", "block", "block_type", "trial", "event",
                                     "stimulus", "stimulus_hash", "detail", "timestamp"});
  for (const EventRow& e : store.event_rows())
    events_csv += csv::line({e.study, exported_participant(e.participant_code, e.participant, e.export_personal),
                            std::to_string(e.session), e.block_id, e.block_type, std::to_string(e.trial_index), e.kind,
                            e.stimulus, e.stimulus_hash, e.detail_json, iso8601_utc(e.timestamp_ms)});
  // The stored protocol texts say what the responses do not (truth, factors, moduli, staircase rules).
  std::vector<std::string> unreadable;
  const auto tables = tidy_tables(rows, stored_protocols(store), &unreadable);

  std::map<std::string, std::size_t> per_study;
  for (const ResponseRow& r : rows) ++per_study[r.study];
  nlohmann::json studies = nlohmann::json::array();
  for (const StudyRecord& s : store.studies())
    studies.push_back({{"id", s.id},
                       {"title", s.title},
                       {"protocol_sha256", s.protocol_sha256},
                       {"protocol_text", s.protocol_text},
                       {"export_personal", s.export_personal},
                       {"responses", per_study[s.id]}});
  const nlohmann::json meta = {
      {"source", is_postgres_uri(db_path) ? store.path() : std::filesystem::path(db_path).filename().string()},
      {"schema_version", ResultsStore::kSchemaVersion},
      {"studies", studies},
      {"counts",
       {{"studies", store.count("studies")},
        {"participants", store.count("participants")},
        {"sessions", store.count("sessions")},
        {"trials", store.count("trials")},
        {"responses", store.count("responses")},
        {"events", store.count("events")}}},
      {"columns", columns}};

  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw InputError(SourceLocation{out_dir, 0, 0}, "cannot create folder: " + ec.message());
  ExportSummary summary;
  summary.csv_path = (std::filesystem::path(out_dir) / "responses.csv").string();
  summary.json_path = (std::filesystem::path(out_dir) / "study.json").string();
  summary.responses = rows.size();
  summary.notices = std::move(unreadable);
  write_file_atomically(summary.csv_path, csv);
  write_file_atomically((std::filesystem::path(out_dir) / "trials.csv").string(), trials_csv);
  write_file_atomically((std::filesystem::path(out_dir) / "events.csv").string(), events_csv);
  for (const auto& [name, text] : tables) {
    write_file_atomically((std::filesystem::path(out_dir) / name).string(), text);
    summary.tables.push_back(name);
  }
  write_file_atomically(summary.json_path, meta.dump(2) + "\n");
  return summary;
}

}  // namespace ms
