// participant_status: the latest session of one participant, read-only; see participant_status.hpp.
#include "studyapp/core/participant_status.hpp"

#include "studyapp/core/export.hpp"
#include "studyapp/core/participant_id.hpp"
#include "studyapp/core/results_store.hpp"
#include "studyapp/core/store_location.hpp"

namespace ms {

ParticipantStatus participant_status(const std::string& db_path, const std::string& study,
                                     const std::string& participant) {
  ParticipantStatus out;
  out.participant = normalize_participant_id(participant);
  if (!store_exists(db_path)) return out;
  const ResultsStore store(db_path, ResultsStore::Mode::read_only);
  out.look_alikes = look_alike_ids(out.participant, store.participant_codes(study));
  const auto pid = store.find_participant(study, out.participant);
  if (!pid) return out;
  const auto last = store.latest_session(*pid);
  if (!last) return out;
  out.state = last->finished_ms ? ParticipantStatus::State::finished : ParticipantStatus::State::unfinished;
  out.session = last->id;
  out.started_ms = last->started_ms;
  out.finished_ms = last->finished_ms;
  out.autopilot = last->autopilot;
  for (const auto& s : store.session_summaries())
    if (s.study == study && s.participant_code == out.participant) {
      ++out.sessions;
      if (s.session == last->id) {
        out.answered = s.responses;
        out.total = s.trials;
      }
    }
  return out;
}

std::string describe(const ParticipantStatus& s) {
  const std::string trials = std::to_string(s.answered) + "/" + std::to_string(s.total);
  switch (s.state) {
    case ParticipantStatus::State::none: return "";
    case ParticipantStatus::State::unfinished:
      return s.participant + " has an unfinished session (" + trials + " trials answered)";
    case ParticipantStatus::State::finished:
      return s.participant + " finished this study on " + iso8601_utc(*s.finished_ms).substr(0, 10) + " (" + trials +
             " trials)";
  }
  return "";
}

}  // namespace ms
