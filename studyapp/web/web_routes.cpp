// route: split the path into segments, dispatch, and turn refusals into JSON errors.
#include "studyapp/web/web_routes.hpp"

#include <vector>

#include "synthesis/input_error.hpp"

namespace ms::web {

namespace {

std::vector<std::string> segments(const std::string& target) {
  const std::string path = target.substr(0, target.find_first_of("?#"));
  std::vector<std::string> parts;
  std::size_t start = 1;
  while (start <= path.size()) {
    const auto slash = path.find('/', start);
    parts.push_back(path.substr(start, slash == std::string::npos ? std::string::npos : slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return parts;
}

WebResponse text_page(int status, const std::string& text) {
  WebResponse r;
  r.status = status;
  r.content_type = "text/html; charset=utf-8";
  r.body = "<!doctype html><meta charset=utf-8><title>ModalStudy</title><p>" + text + "</p>";
  return r;
}

void require(const WebRequest& r, const char* method) {
  if (r.method != method) throw Refusal(405, std::string("use ") + method + " here");
}

bool is_experimenter(const ExperimenterView* experimenter, const std::vector<std::string>& s) {
  return experimenter && s.size() >= 2 && (s[0] == "x" || s[0] == "xapi") && experimenter->admits(s[1]);
}

// The experimenter's pages; a token that is not the experimenter's learns nothing but 404.
WebResponse dispatch_experimenter(const ExperimenterView* experimenter, const ClientFiles& client,
                                  const std::vector<std::string>& s, const WebRequest& r) {
  if (!is_experimenter(experimenter, s)) {
    if (s[0] == "x") return text_page(404, "This link is not part of the study. Please check it.");
    throw Refusal(404, "no such page");
  }
  require(r, "GET");
  if (s[0] == "x" && s.size() == 2) {
    auto page = client.get("/client/experimenter.html");
    if (!page) throw Refusal(404, "no such file");
    page->cacheable = false;
    return *page;
  }
  if (s.size() == 3 && s[2] == "completion") return experimenter->completion();
  if (s.size() == 3 && s[2] == "export") return experimenter->export_list();
  if (s.size() == 4 && s[2] == "export") return experimenter->export_file(s[3]);
  throw Refusal(404, "no such page");
}

WebResponse dispatch(StudyService& service, const ClientFiles& client, const ExperimenterView* experimenter,
                     const WebRequest& r) {
  const std::vector<std::string> s = segments(r.target);
  if (r.target.empty() || r.target.front() != '/') throw Refusal(400, "the request target must be a path");
  if (s.size() == 1 && s[0].empty()) {
    require(r, "GET");
    return text_page(200, "Please open the link you were given for this study.");
  }
  if (s[0] == "client") {
    require(r, "GET");
    if (auto file = client.get(r.target.substr(0, r.target.find_first_of("?#")))) return *file;
    throw Refusal(404, "no such file");
  }
  if (s[0] == "s" && s.size() == 2) {
    require(r, "GET");
    if (!service.knows(s[1])) return text_page(404, "This link is not part of the study. Please check it.");
    return client.index();
  }
  if ((s[0] == "x" || s[0] == "xapi") && s.size() >= 2) return dispatch_experimenter(experimenter, client, s, r);
  if (s[0] == "api" && s.size() >= 3) {
    const std::string& token = s[1];
    const std::string& what = s[2];
    if (s.size() == 3 && what == "trial") return require(r, "GET"), service.trial(token);
    if (s.size() == 3 && what == "answer") return require(r, "POST"), service.answer(token, r.body);
    if (s.size() == 3 && what == "event") return require(r, "POST"), service.event(token, r.body);
    if (s.size() == 3 && what == "render") return require(r, "POST"), service.render(token, r.body);
    if (s.size() == 4 && what == "sound") return require(r, "GET"), service.sound(token, s[3]);
  }
  throw Refusal(404, "no such page");
}

}  // namespace

WebResponse route(StudyService& service, const ClientFiles& client, const WebRequest& request, RateLimit* limit,
                  const ExperimenterView* experimenter) {
  try {
    if (limit) {
      const std::vector<std::string> s = segments(request.target);
      const bool client_file = !s.empty() && s[0] == "client";
      const bool names_link = s.size() >= 2 && (s[0] == "api" || s[0] == "s") && service.knows(s[1]);
      const std::string key = names_link ? s[1] : is_experimenter(experimenter, s) ? "experimenter" : std::string();
      if (!client_file && !limit->allow(key))
        throw Refusal(429, "too many requests; please wait a moment");
    }
    return dispatch(service, client, experimenter, request);
  } catch (const Refusal& e) {
    return error_response(e.status(), e.what());
  } catch (const std::exception& e) {
    // Not the participant's doing (a store or cache failure): nothing half-done was committed.
    WebResponse r = error_response(500, "the server could not do this; please try again");
    r.log_note = e.what();
    return r;
  }
}

std::string loggable_target(const WebRequest& request) {
  const std::vector<std::string> s = segments(request.target);
  std::string route = "/";
  if (!s.empty() && (s[0] == "api" || s[0] == "s" || s[0] == "x" || s[0] == "xapi")) {
    route += s[0] + (s.size() > 1 ? "/*" : "");
    if ((s[0] == "api" || s[0] == "xapi") && s.size() > 2) route += "/" + (s[2].size() <= 8 ? s[2] : std::string("?"));
    if (s.size() > 3) route += "/*";
  } else if (!s.empty() && s[0] == "client") {
    route = "/client/*";
  } else if (!s.empty() && !s[0].empty()) {
    route += "?";  // an unknown path is not echoed (it may hold anything)
  }
  return request.method.substr(0, 8) + " " + route;
}

}  // namespace ms::web
