// The server's URL space, and the only place a request target is read:
//   GET  /                         a page saying to open one's participant link
//   GET  /s/<token>                the client's page (index.html) for a known link
//   GET  /client/<file>            a client file (ClientFiles)
//   GET  /api/<token>/trial        the current trial's page     POST /api/<token>/answer
//   POST /api/<token>/event        play/stop/switch             POST /api/<token>/render (adjust)
//   GET  /api/<token>/sound/<id>   one sound of the trial last sent
//   GET  /x/<token>                the experimenter's page (experimenter.html) for the experimenter token
//   GET  /xapi/<token>/completion  participants and completion     GET /xapi/<token>/export  its files
//   GET  /xapi/<token>/export/<file>   one file of the export, as a download
// Anything else is 404 (or 405 for a known path with another method).
#pragma once
#include <string>

#include "studyapp/web/client_files.hpp"
#include "studyapp/web/experimenter_view.hpp"
#include "studyapp/web/rate_limit.hpp"
#include "studyapp/web/study_service.hpp"
#include "studyapp/web/web_request.hpp"

namespace ms::web {

// Never throws: refusals and internal errors become their responses. With `limit`, requests naming a
// link count against that link's bucket, the experimenter's against theirs, and all other requests but
// client files against one shared bucket; over the limit: 429. Without `experimenter` the /x pages are 404.
WebResponse route(StudyService& service, const ClientFiles& client, const WebRequest& request,
                  RateLimit* limit = nullptr, const ExperimenterView* experimenter = nullptr);

// What a log line may say about a request: its method and route with every token and id elided
// ("POST /api/*/answer"), so the log holds no link and nothing a participant typed.
std::string loggable_target(const WebRequest& request);

}  // namespace ms::web
