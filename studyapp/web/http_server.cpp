// HttpServer: Beast's asynchronous accept / read / write loop, one strand per connection.
#include "studyapp/web/http_server.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <chrono>
#include <optional>
#include <thread>
#include <vector>

#include "synthesis/input_error.hpp"

namespace ms::web {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

http::response<http::string_body> to_http(const WebResponse& r, unsigned version, bool keep_alive) {
  http::response<http::string_body> res{static_cast<http::status>(r.status), version};
  res.set(http::field::content_type, r.content_type);
  res.set(http::field::cache_control, r.cacheable ? "no-cache" : "no-store");
  res.set("X-Content-Type-Options", "nosniff");
  res.set("X-Frame-Options", "DENY");
  res.set("Referrer-Policy", "no-referrer");  // the link's token never leaves in a Referer header
  res.set("Content-Security-Policy", "default-src 'self'; frame-ancestors 'none'");
  if (!r.download_name.empty()) res.set(http::field::content_disposition, "attachment; filename=\"" + r.download_name + "\"");
  res.keep_alive(keep_alive);
  res.body() = r.body;
  res.prepare_payload();
  return res;
}

class Connection : public std::enable_shared_from_this<Connection> {
 public:
  Connection(tcp::socket socket, const HttpOptions& options, const Handler& handler, const Logger& log)
      : stream_(std::move(socket)), options_(options), handler_(handler), log_(log) {}

  void start() { net::dispatch(stream_.get_executor(), beast::bind_front_handler(&Connection::read, shared_from_this())); }

 private:
  void read() {
    parser_.emplace();
    parser_->header_limit(16 * 1024);
    parser_->body_limit(options_.body_limit_bytes);
    stream_.expires_after(std::chrono::seconds(options_.timeout_s));
    http::async_read(stream_, buffer_, *parser_, beast::bind_front_handler(&Connection::on_read, shared_from_this()));
  }

  void on_read(beast::error_code ec, std::size_t) {
    if (ec == http::error::body_limit) {
      if (log_) log_("refused a request body over " + std::to_string(options_.body_limit_bytes) + " bytes");
      return write(error_response(413, "the request body is larger than " + std::to_string(options_.body_limit_bytes) +
                                           " bytes"),
                   11, false);
    }
    if (ec) return close();  // end of stream, a time-out, a dropped connection: nothing was handled
    const auto& req = parser_->get();
    WebRequest request{std::string(req.method_string()), std::string(req.target()), req.body()};
    write(handler_(request), req.version(), req.keep_alive());
  }

  void write(const WebResponse& response, unsigned version, bool keep_alive) {
    auto res = std::make_shared<http::response<http::string_body>>(to_http(response, version, keep_alive));
    stream_.expires_after(std::chrono::seconds(options_.timeout_s));
    http::async_write(stream_, *res, [self = shared_from_this(), res, keep_alive](beast::error_code ec, std::size_t) {
      if (ec || !keep_alive) return self->close();
      self->read();
    });
  }

  void close() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
  }

  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  const HttpOptions& options_;
  const Handler& handler_;
  const Logger& log_;
};

}  // namespace

struct HttpServer::Impl {
  HttpOptions options;
  Handler handler;
  Logger log;
  net::io_context ioc;
  tcp::acceptor acceptor{ioc};
  net::signal_set signals{ioc};

  void accept() {
    acceptor.async_accept(net::make_strand(ioc), [this](beast::error_code ec, tcp::socket socket) {
      if (!ec) std::make_shared<Connection>(std::move(socket), options, handler, log)->start();
      if (acceptor.is_open()) accept();
    });
  }
};

HttpServer::HttpServer(const HttpOptions& options, Handler handler, Logger log) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  impl_->handler = std::move(handler);
  impl_->log = std::move(log);
  const std::string where = options.host + ":" + std::to_string(options.port);
  beast::error_code ec;
  const auto address = net::ip::make_address(options.host, ec);
  if (ec) throw InputError("--host " + options.host + ": not an IP address (" + ec.message() + ")");
  const tcp::endpoint endpoint{address, options.port};
  impl_->acceptor.open(endpoint.protocol(), ec);
  if (!ec) impl_->acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) impl_->acceptor.bind(endpoint, ec);
  if (!ec) impl_->acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) throw InputError("cannot listen on " + where + ": " + ec.message());
  if (options.stop_on_signals) {
    impl_->signals.add(SIGINT);
    impl_->signals.add(SIGTERM);
    impl_->signals.async_wait([this](beast::error_code, int) { stop(); });
  }
  impl_->accept();
}

HttpServer::~HttpServer() { stop(); }

unsigned short HttpServer::port() const { return impl_->acceptor.local_endpoint().port(); }

void HttpServer::run() {
  std::vector<std::thread> more;
  for (int i = 1; i < impl_->options.threads; ++i) more.emplace_back([this] { impl_->ioc.run(); });
  impl_->ioc.run();
  for (std::thread& t : more) t.join();
}

void HttpServer::stop() { impl_->ioc.stop(); }

}  // namespace ms::web
