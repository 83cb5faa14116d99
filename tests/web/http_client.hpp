// A small HTTP client for the server tests (Boost.Beast's client side over loopback), and raw byte
// exchanges for requests a browser would never send (a dropped body, a path a browser normalises).
#pragma once
#include <string>

namespace ms::test {

struct HttpReply {
  int status = 0;
  std::string content_type;
  std::string body;
};

// One request on a fresh connection to 127.0.0.1:port.
HttpReply http_call(unsigned short port, const std::string& method, const std::string& target, const std::string& body = "");

// Sends `bytes` as they are, then (close_early) closes the connection at once, or reads the reply until
// the server closes it or 5 s pass. Returns what was read.
std::string raw_exchange(unsigned short port, const std::string& bytes, bool close_early);

}  // namespace ms::test
