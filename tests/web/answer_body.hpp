// A valid answer to a trial page of the web tests' studies (instructions, ab, identify with label "two",
// mushra), as the browser client sends it; shared by tests_web and bench_serve.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace ms::test {

inline nlohmann::json answer_body(const nlohmann::json& page) {
  nlohmann::json body{{"trial", page["trial"]}, {"step", page["step"]}, {"rt_ms", 900}};
  const std::string type = page["type"];
  if (type == "instructions") body["answer"] = "ok";
  if (type == "ab") body["answer"] = "A";
  if (type == "identify") body["answer"] = "two";
  if (type == "mushra") {
    body["answer"] = nlohmann::json::object();
    body["moved"] = nlohmann::json::array();
    for (std::size_t k = 1; k < page["sounds"].size(); ++k) {
      body["answer"][page["sounds"][k]["id"].get<std::string>()] = 40 + 10 * static_cast<int>(k);
      body["moved"].push_back(page["sounds"][k]["id"]);
    }
  }
  return body;
}

}  // namespace ms::test
