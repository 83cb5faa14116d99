// The experimenter's page behind `serve`: who takes part, how far each participant got, and the export
// as downloads. It has its own token (128 random bits, drawn at every start, never a participant's), is
// read from the store only (what it shows is what was committed) and writes nothing: the downloads are
// the files `modalstudy export` writes, made by the core's export_results into a private temporary
// folder for each request.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studyapp/core/protocol.hpp"
#include "studyapp/web/participant_links.hpp"
#include "studyapp/web/web_request.hpp"

namespace ms::web {

class ExperimenterView {
 public:
  // Draws the token; `links` are the participant links (the new token differs from each of them).
  ExperimenterView(const Protocol& protocol, std::string db_path, std::vector<ParticipantLink> links);

  const std::string& token() const { return token_; }
  bool admits(const std::string& token) const;  // compared in constant time

  // {"study", "title", "participants": [{"participant", "state": not started|unfinished|finished,
  //  "answered", "scheduled", "sessions"}], "answered", "scheduled", "finished"} from the store.
  WebResponse completion() const;
  // {"responses", "files": [names], "notices": [...]}: what an export of the store holds now.
  WebResponse export_list() const;
  // One file of the export (responses.csv, study.json, trials.csv, events.csv, <type>.csv), as a
  // download; Refusal 404 for a name the export does not write, 409 while the store holds no study.
  WebResponse export_file(const std::string& name) const;

 private:
  const Protocol* protocol_;
  std::string db_path_;
  std::vector<ParticipantLink> links_;
  std::string token_;
};

}  // namespace ms::web
