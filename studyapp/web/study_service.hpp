// The study as `serve` offers it, without HTTP: one Session per participant link (opened on its first
// request, resumed at the first unanswered trial after a reload or a restart), the trial last sent to
// each, and the requests a page makes. Every answer is checked (the trial and step it answers must be
// the ones last sent, the window's answer gate, response_format) and committed before the next trial
// is returned; a refused request leaves the store as it was.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "studyapp/web/participant_links.hpp"
#include "studyapp/web/web_request.hpp"

namespace ms::web {

struct ServiceSetup {
  const Protocol* protocol = nullptr;
  std::string protocol_text;     // stored with the study (its hash ties the database to the protocol)
  StimulusCache* cache = nullptr;
  std::string cache_dir;         // where the cache keeps <hash>.wav (sounds are served from there)
  std::string db_path;
  std::vector<ParticipantLink> links;
};

class StudyService {
 public:
  explicit StudyService(ServiceSetup setup);
  ~StudyService();
  StudyService(const StudyService&) = delete;
  StudyService& operator=(const StudyService&) = delete;

  bool knows(const std::string& token) const;
  const Protocol& protocol() const { return *setup_.protocol; }

  // Each returns the JSON response, or throws Refusal (status and one-line reason).
  // GET trial: {"title", "page"} with the current trial's page, or page {"finished": true}.
  WebResponse trial(const std::string& token);
  // POST answer {"trial", "step", "answer", "rt_ms"[, "moved": [ids]]}: {"feedback"?, "break", "page"}.
  WebResponse answer(const std::string& token, const std::string& body);
  // POST event {"trial", "step", "kind": play|stop|switch, "sound": id[, "at_ms", "position_s"]}.
  WebResponse event(const std::string& token, const std::string& body);
  // POST render {"trial", "positions": [0..100 per slider]}: the adjust variant {"sound", "values"}.
  WebResponse render(const std::string& token, const std::string& body);
  // GET sound/<id>: the WAV of a sound of the trial last sent.
  WebResponse sound(const std::string& token, const std::string& id);

 private:
  struct Participant;
  Participant& find(const std::string& token) const;
  void open(Participant& p);
  nlohmann::json current_page(Participant& p);
  // A POST about the trial last sent: the participant found, the body parsed, the participant's lock
  // held and the trial and step it names checked before `handle` runs.
  WebResponse about_sent_trial(const std::string& token, const std::string& body,
                               const std::function<WebResponse(Participant&, const nlohmann::json&)>& handle);

  ServiceSetup setup_;
  std::map<std::string, std::unique_ptr<Participant>> by_token_;  // fixed after construction
};

}  // namespace ms::web
