// StudyServer: protocol check, stimulus cache, links, StudyService, ClientFiles, HttpServer, in order.
#include "studyapp/web/study_server.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "studyapp/core/store_location.hpp"
#include "studyapp/web/client_files.hpp"
#include "studyapp/web/experimenter_view.hpp"
#include "studyapp/web/rate_limit.hpp"
#include "studyapp/web/study_service.hpp"
#include "studyapp/web/web_routes.hpp"
#include "synthesis/bounded_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms::web {

namespace fs = std::filesystem;

namespace {

// Issued links are kept beside the database, so a restarted server hands out the same ones.
std::vector<ParticipantLink> issued_links(const std::string& path, std::size_t count) {
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    std::vector<ParticipantLink> links = issue_participants(count);
    write_participant_list(path, links);
    return links;
  }
  std::vector<ParticipantLink> links = read_participant_list(path);
  if (links.size() != count)
    throw InputError(SourceLocation{path, 0, 0}, "holds " + std::to_string(links.size()) + " links, not the " +
                                                     std::to_string(count) + " --participants asks for; pass it as "
                                                     "--participant-list, or remove it to issue new links");
  return links;
}

}  // namespace

struct StudyServer::Impl {
  ProtocolCheck check;
  std::string db_path, links_path;
  std::unique_ptr<StimulusCache> cache;
  std::unique_ptr<StudyService> service;
  std::unique_ptr<ExperimenterView> experimenter;
  std::unique_ptr<ClientFiles> client;
  std::unique_ptr<RateLimit> limit;
  std::unique_ptr<HttpServer> http;
  std::vector<ParticipantLink> links;
};

StudyServer::StudyServer(const ServeOptions& o, Logger log) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  if ((o.participants == 0) == o.participant_list.empty())
    throw InputError("give either --participants N or --participant-list FILE");
  ValidateOptions validate;
  validate.allow_outside = o.allow_outside;
  m.check = check_protocol_file(o.protocol_path, validate);
  if (!m.check.problems.empty() || !m.check.protocol) throw InvalidProtocol(m.check.problems);
  const Protocol& protocol = *m.check.protocol;
  m.db_path = o.db_path.empty() ? default_db_path(o.protocol_path, protocol.study) : o.db_path;
  // The links and the stimulus cache are local files: beside a SQLite store, and where a SQLite store
  // would be (the protocol's results/ folder) when the store is a PostgreSQL server.
  const std::string local_store =
      is_postgres_uri(m.db_path) ? default_db_path(o.protocol_path, protocol.study) : m.db_path;
  const fs::path db_dir = fs::path(local_store).parent_path();
  if (!db_dir.empty()) fs::create_directories(db_dir);
  const std::string cache_dir = o.cache_dir.empty() ? (db_dir / "stimulus-cache").string() : o.cache_dir;
  if (o.participant_list.empty()) {
    m.links_path = o.links_path.empty() ? local_store + ".links.csv" : o.links_path;
    m.links = issued_links(m.links_path, o.participants);
  } else {
    m.links = read_participant_list(o.participant_list);
  }
  m.client = std::make_unique<ClientFiles>(o.client_dir.empty() ? default_client_folder(MODALSTUDY_WEB_CLIENT_SOURCE)
                                                                : o.client_dir);
  m.cache = std::make_unique<StimulusCache>(protocol, cache_dir);
  m.cache->prepare_all([&](std::size_t done, std::size_t total, const std::string&) {
    if (log) log("rendered " + std::to_string(done) + "/" + std::to_string(total) + " stimuli");
  });
  ServiceSetup setup;
  setup.protocol = &protocol;
  setup.protocol_text = read_bounded_file(o.protocol_path, kYamlFileLimit);
  setup.cache = m.cache.get();
  setup.cache_dir = cache_dir;
  setup.db_path = m.db_path;
  setup.links = m.links;
  m.service = std::make_unique<StudyService>(std::move(setup));
  m.experimenter = std::make_unique<ExperimenterView>(protocol, m.db_path, m.links);
  if (o.rate_per_second > 0) m.limit = std::make_unique<RateLimit>(o.rate_burst, o.rate_per_second);
  Handler handler = [&m, log](const WebRequest& request) {
    const auto start = std::chrono::steady_clock::now();
    WebResponse response = route(*m.service, *m.client, request, m.limit.get(), m.experimenter.get());
    if (log) {
      const auto ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      char took[32];
      std::snprintf(took, sizeof took, " %.1f ms", ms);
      log(loggable_target(request) + " " + std::to_string(response.status) + took +
          (response.log_note.empty() ? "" : " (" + response.log_note + ")"));
    }
    return response;
  };
  m.http = std::make_unique<HttpServer>(o.http, std::move(handler), log);
}

StudyServer::~StudyServer() = default;

unsigned short StudyServer::port() const { return impl_->http->port(); }
const std::vector<ParticipantLink>& StudyServer::links() const { return impl_->links; }
const std::string& StudyServer::db_path() const { return impl_->db_path; }
const std::string& StudyServer::links_path() const { return impl_->links_path; }

namespace {

std::string without_trailing_slashes(std::string base) {
  while (!base.empty() && base.back() == '/') base.pop_back();
  return base;
}

}  // namespace

std::string StudyServer::link_url(const ParticipantLink& link, const std::string& base_url) const {
  return without_trailing_slashes(base_url) + "/s/" + link.token;
}

const std::string& StudyServer::experimenter_token() const { return impl_->experimenter->token(); }

std::string StudyServer::experimenter_url(const std::string& base_url) const {
  return without_trailing_slashes(base_url) + "/x/" + experimenter_token();
}

void StudyServer::run() { impl_->http->run(); }
void StudyServer::stop() { impl_->http->stop(); }

}  // namespace ms::web
