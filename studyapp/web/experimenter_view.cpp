// ExperimenterView: completion from the store's session summaries, downloads from export_results.
#include "studyapp/web/experimenter_view.hpp"

#include <openssl/crypto.h>

#include <algorithm>
#include <filesystem>

#include "studyapp/core/export.hpp"
#include "studyapp/core/results_store.hpp"
#include "studyapp/core/schedule.hpp"
#include "studyapp/core/store_location.hpp"
#include "studyapp/web/web_token.hpp"
#include "synthesis/bounded_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms::web {

namespace fs = std::filesystem;

namespace {

// Runs the core's export into a fresh private folder, hands the summary and folder to `use`, and
// removes the folder whatever happens.
template <typename Use>
auto with_export(const std::string& db_path, Use use) {
  if (!store_exists(db_path)) throw Refusal(409, "nobody has answered yet: there is nothing to export");
  const fs::path dir = fs::temp_directory_path() / ("modalstudy-export-" + new_token());
  struct Remove {
    fs::path dir;
    ~Remove() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } remove{dir};
  fs::create_directory(dir);
  fs::permissions(dir, fs::perms::owner_all);
  const ExportSummary summary = export_results(db_path, dir.string());
  return use(summary, dir);
}

std::vector<std::string> exported_files(const ExportSummary& s) {
  std::vector<std::string> files{"responses.csv", "study.json", "trials.csv", "events.csv"};
  files.insert(files.end(), s.tables.begin(), s.tables.end());
  return files;
}

}  // namespace

ExperimenterView::ExperimenterView(const Protocol& protocol, std::string db_path, std::vector<ParticipantLink> links)
    : protocol_(&protocol), db_path_(std::move(db_path)), links_(std::move(links)) {
  const auto taken = [this](const std::string& t) {
    for (const ParticipantLink& l : links_)
      if (l.token == t) return true;
    return false;
  };
  do token_ = new_token();
  while (taken(token_));
}

bool ExperimenterView::admits(const std::string& token) const {
  return token.size() == token_.size() && CRYPTO_memcmp(token.data(), token_.data(), token_.size()) == 0;
}

WebResponse ExperimenterView::completion() const {
  std::vector<SessionSummary> summaries;
  if (store_exists(db_path_)) summaries = ResultsStore(db_path_, ResultsStore::Mode::read_only).session_summaries();
  nlohmann::json participants = nlohmann::json::array();
  std::int64_t answered = 0, scheduled = 0, finished = 0;
  for (const ParticipantLink& link : links_) {
    const SessionSummary* latest = nullptr;
    int sessions = 0;
    for (const SessionSummary& s : summaries)
      if (s.study == protocol_->study && s.participant_code == link.participant) {
        ++sessions;
        if (!latest || s.session > latest->session) latest = &s;
      }
    nlohmann::json row{{"participant", link.participant}, {"sessions", sessions}};
    if (latest) {
      row["state"] = latest->finished_ms ? "finished" : "unfinished";
      row["answered"] = latest->responses;
      row["scheduled"] = latest->trials;
    } else {
      row["state"] = "not started";
      row["answered"] = 0;
      row["scheduled"] = make_schedule(*protocol_, link.participant).trials.size();
    }
    answered += row["answered"].get<std::int64_t>();
    scheduled += row["scheduled"].get<std::int64_t>();
    finished += latest && latest->finished_ms ? 1 : 0;
    participants.push_back(std::move(row));
  }
  return json_response({{"study", protocol_->study}, {"title", protocol_->title}, {"participants", participants},
                        {"answered", answered}, {"scheduled", scheduled}, {"finished", finished}});
}

WebResponse ExperimenterView::export_list() const {
  if (!store_exists(db_path_)) return json_response({{"responses", 0}, {"files", nlohmann::json::array()},
                                                     {"notices", nlohmann::json::array()}});
  return with_export(db_path_, [](const ExportSummary& s, const fs::path&) {
    return json_response({{"responses", s.responses}, {"files", exported_files(s)}, {"notices", s.notices}});
  });
}

WebResponse ExperimenterView::export_file(const std::string& name) const {
  return with_export(db_path_, [&name](const ExportSummary& s, const fs::path& dir) {
    const std::vector<std::string> files = exported_files(s);
    // Only a name the export itself wrote reaches the file system, and only inside its own folder.
    const auto it = std::find(files.begin(), files.end(), name);
    if (it == files.end()) throw Refusal(404, "the export has no file of that name");
    WebResponse r;
    r.content_type = it->ends_with(".json") ? "application/json" : "text/csv; charset=utf-8";
    r.body = read_bounded_file((dir / *it).string(), kCsvFileLimit);
    r.download_name = *it;
    return r;
  });
}

}  // namespace ms::web
