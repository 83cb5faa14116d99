// One HTTP exchange as the study's handlers see it, without the HTTP library: the request's method,
// target and body in, a status, content type and body out. Refusals carry a one-line reason.
#pragma once
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace ms::web {

struct WebRequest {
  std::string method;  // "GET", "POST", ...
  std::string target;  // path and query as sent, e.g. /api/<token>/trial
  std::string body;
};

struct WebResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  bool cacheable = false;  // client files may be cached; answers, pages and sounds never
  std::string log_note;    // for the server's log only (why a 500 happened), never sent
  std::string download_name;  // "" = shown in the page; else saved as this file (Content-Disposition)
};

// A refused request: its HTTP status and the reason the response's {"error": ...} gives.
class Refusal : public std::runtime_error {
 public:
  Refusal(int status, const std::string& reason) : std::runtime_error(reason), status_(status) {}
  int status() const { return status_; }

 private:
  int status_;
};

WebResponse json_response(const nlohmann::json& value, int status = 200);
WebResponse error_response(int status, const std::string& reason);

// The body as one JSON object, or Refusal 400 "request body: line L, column C: problem".
nlohmann::json parse_json_body(const std::string& body);
// Fields of a parsed body, each checked; Refusal 400 "request body: 'key' must be ..." otherwise.
std::size_t index_field(const nlohmann::json& body, const char* key);
double number_field(const nlohmann::json& body, const char* key, double min, double max);
std::string string_field(const nlohmann::json& body, const char* key, std::size_t max_bytes);
const nlohmann::json& field(const nlohmann::json& body, const char* key);

}  // namespace ms::web
