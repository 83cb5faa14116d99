// JSON bodies: nlohmann's parser (its error located at line and column), then typed fields.
#include "studyapp/web/web_request.hpp"

namespace ms::web {

WebResponse json_response(const nlohmann::json& value, int status) {
  WebResponse r;
  r.status = status;
  r.body = value.dump();
  return r;
}

WebResponse error_response(int status, const std::string& reason) {
  return json_response(nlohmann::json{{"error", reason}}, status);
}

nlohmann::json parse_json_body(const std::string& body) {
  nlohmann::json value;
  try {
    value = nlohmann::json::parse(body);
  } catch (const nlohmann::json::parse_error& e) {
    // what() = "[json.exception.parse_error.101] parse error at line 1, column 5: ..."; keep from "line".
    const std::string what = e.what();
    const auto at = what.find("line ");
    throw Refusal(400, "request body: " + (at == std::string::npos ? what : what.substr(at)));
  }
  if (!value.is_object()) throw Refusal(400, "request body: line 1, column 1: expected a JSON object");
  return value;
}

const nlohmann::json& field(const nlohmann::json& body, const char* key) {
  const auto it = body.find(key);
  if (it == body.end()) throw Refusal(400, std::string("request body: '") + key + "' is missing");
  return *it;
}

std::size_t index_field(const nlohmann::json& body, const char* key) {
  const nlohmann::json& v = field(body, key);
  if (!v.is_number_unsigned()) throw Refusal(400, std::string("request body: '") + key + "' must be an integer >= 0");
  return v.get<std::size_t>();
}

double number_field(const nlohmann::json& body, const char* key, double min, double max) {
  const nlohmann::json& v = field(body, key);
  if (!v.is_number() || !(v.get<double>() >= min && v.get<double>() <= max))
    throw Refusal(400, std::string("request body: '") + key + "' must be a number in [" + nlohmann::json(min).dump() +
                           ", " + nlohmann::json(max).dump() + "]");
  return v.get<double>();
}

std::string string_field(const nlohmann::json& body, const char* key, std::size_t max_bytes) {
  const nlohmann::json& v = field(body, key);
  if (!v.is_string() || v.get_ref<const std::string&>().size() > max_bytes)
    throw Refusal(400, std::string("request body: '") + key + "' must be a string of at most " +
                           std::to_string(max_bytes) + " bytes");
  return v.get<std::string>();
}

}  // namespace ms::web
