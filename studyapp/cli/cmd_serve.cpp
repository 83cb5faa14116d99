// modalstudy serve PROTOCOL.yaml [--db FILE] [--host 127.0.0.1] [--port 8080]
//                  [--participants N | --participant-list FILE] [--base-url URL]
// The study in participants' browsers: prints the experimenter's page (a new token at every start) and
// one link per participant (to stdout, for the experimenter), then serves until Ctrl-C. The request
// log (stderr) names no link or token.
#include <iostream>
#include <mutex>

#include "studyapp/cli/commands.hpp"
#include "studyapp/core/store_location.hpp"
#include "studyapp/web/study_server.hpp"

namespace ms::cli {

void register_serve(CLI::App& app) {
  struct Options {
    web::ServeOptions serve;
    std::string base_url;
    int port = 8080;
    bool quiet = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("serve", "Run a study in participants' browsers (HTTP; TLS by a reverse proxy)");
  cmd->add_option("protocol", opt->serve.protocol_path, "Protocol file (YAML)")->required();
  cmd->add_option("--db", opt->serve.db_path, "Results database: a file (default <protocol dir>/results/<study>.sqlite)"
                 " or a postgresql://user@host:port/dbname URI");
  cmd->add_option("--host", opt->serve.http.host, "Address to listen on (default 127.0.0.1: this machine only)");
  cmd->add_option("--port", opt->port, "Port (default 8080; 0 = any free port)")->check(CLI::Range(0, 65535));
  auto* n = cmd->add_option("--participants", opt->serve.participants, "Issue N participant links (kept in --links)")
                ->check(CLI::Range(1, 100000));
  auto* list = cmd->add_option("--participant-list", opt->serve.participant_list,
                               "CSV participant,token of the links to accept (tokens: 32-128 hex digits)");
  n->excludes(list);
  cmd->add_option("--links", opt->serve.links_path,
                  "Where issued links are kept (default <db>.links.csv; for a PostgreSQL store "
                  "<protocol dir>/results/<study>.sqlite.links.csv; mode 0600)");
  cmd->add_option("--cache", opt->serve.cache_dir,
                  "Rendered-stimulus cache folder (default <db dir>/stimulus-cache; for a PostgreSQL store "
                  "<protocol dir>/results/stimulus-cache)");
  cmd->add_option("--client", opt->serve.client_dir, "Browser client folder (default the data folder's web/)");
  cmd->add_option("--base-url", opt->base_url, "Public address printed in the links (e.g. https://study.example.org)");
  cmd->add_option("--body-limit", opt->serve.http.body_limit_bytes, "Largest request body in bytes (default 65536)");
  cmd->add_option("--rate-limit", opt->serve.rate_per_second,
                  "Requests per second one link may make after a burst of 300 (default 100; 0 = no limit)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--allow-outside", opt->serve.allow_outside, "Allow stimulus files outside the protocol's folder");
  cmd->add_flag("--quiet", opt->quiet, "No request log on stderr");
  cmd->callback([opt] {
    opt->serve.http.port = static_cast<unsigned short>(opt->port);
    opt->serve.http.stop_on_signals = true;
    auto log_mutex = std::make_shared<std::mutex>();
    web::Logger log;
    if (!opt->quiet)
      log = [log_mutex](const std::string& line) {
        const std::lock_guard<std::mutex> lock(*log_mutex);
        std::cerr << line << "\n";
      };
    web::StudyServer server(opt->serve, log);
    const std::string base = opt->base_url.empty()
                                 ? "http://" + opt->serve.http.host + ":" + std::to_string(server.port())
                                 : opt->base_url;
    std::cout << "serving " << opt->serve.protocol_path << " into " << location_without_password(server.db_path()) << " at http://"
              << opt->serve.http.host << ":" << server.port() << "\n";
    if (!server.links_path().empty()) std::cout << "links kept in " << server.links_path() << "\n";
    std::cout << "experimenter " << server.experimenter_url(base) << "\n";
    for (const auto& link : server.links()) std::cout << link.participant << " " << server.link_url(link, base) << "\n";
    std::cout << "Ctrl-C stops the server" << std::endl;
    server.run();
    std::cout << "stopped" << std::endl;
  });
}

}  // namespace ms::cli
