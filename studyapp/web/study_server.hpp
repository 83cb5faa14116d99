// `modalstudy serve` as one object: checks the protocol as `protocol check` does, renders every stimulus
// into the cache, reads or issues the participant links, opens the HTTP server and routes requests to
// the StudyService. The command line and the tests build it the same way.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "studyapp/web/http_server.hpp"
#include "studyapp/web/participant_links.hpp"

namespace ms::web {

struct ServeOptions {
  std::string protocol_path;
  std::string db_path;            // "" = <protocol dir>/results/<study>.sqlite
  std::string cache_dir;          // "" = <db dir>/stimulus-cache
  std::string client_dir;         // "" = the data folder's web/ (default_client_folder)
  std::size_t participants = 0;   // issue this many links ...
  std::string participant_list;   // ... or read them (participant,token)
  std::string links_path;         // issued links are kept here ("" = <db>.links.csv) and reused
  bool allow_outside = false;
  double rate_burst = 300;        // requests a link may make at once ...
  double rate_per_second = 100;   // ... and per second after that (0 = no limit)
  HttpOptions http;
};

class StudyServer {
 public:
  // Throws InvalidProtocol, or InputError naming the file or option that is wrong.
  StudyServer(const ServeOptions& options, Logger log = {});
  ~StudyServer();

  unsigned short port() const;
  const std::vector<ParticipantLink>& links() const;
  const std::string& db_path() const;
  const std::string& links_path() const;  // "" when the links came from --participant-list
  std::string link_url(const ParticipantLink& link, const std::string& base_url) const;  // base/s/<token>
  const std::string& experimenter_token() const;  // drawn afresh at every start
  std::string experimenter_url(const std::string& base_url) const;                        // base/x/<token>
  void run();   // until stop() or a signal (options.http.stop_on_signals)
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ms::web
