// The HTTP/1.1 server under `serve` (Boost.Beast over Asio; the only file that includes Beast): accepts
// connections on one address, reads each request with a header and body size limit and a time limit,
// hands it to the handler and writes the response with the safety headers every page gets.
#pragma once
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "studyapp/web/web_request.hpp"

namespace ms::web {

struct HttpOptions {
  std::string host = "127.0.0.1";          // loopback unless the experimenter says otherwise
  unsigned short port = 8080;              // 0 = any free port (see HttpServer::port)
  std::size_t body_limit_bytes = 64 * 1024;  // larger bodies get 413 and the connection is closed
  int threads = 2;
  int timeout_s = 30;                      // per request read and response write
  bool stop_on_signals = false;            // SIGINT / SIGTERM end run()
};

using Handler = std::function<WebResponse(const WebRequest&)>;
using Logger = std::function<void(const std::string&)>;

class HttpServer {
 public:
  // Binds and listens at once; throws InputError naming host:port if that address cannot be used.
  HttpServer(const HttpOptions& options, Handler handler, Logger log = {});
  ~HttpServer();  // stops and joins
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  unsigned short port() const;  // the bound port
  void run();                   // serves on options.threads threads until stop() (or a signal)
  void stop();                  // thread-safe

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ms::web
