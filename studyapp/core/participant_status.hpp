// What a results database already holds for one participant of a study, for the start page and the
// command line to say before a session starts: nothing yet, an unfinished session (how far it got),
// or a finished one (when), and existing ids that differ from the typed one only by case or spaces.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ms {

struct ParticipantStatus {
  enum class State { none, unfinished, finished };
  State state = State::none;
  std::string participant;  // as normalised
  std::int64_t session = 0, sessions = 0;  // the latest session, and how many the participant has
  std::int64_t started_ms = 0;
  std::optional<std::int64_t> finished_ms;
  std::int64_t answered = 0, total = 0;  // trials of the latest session
  bool autopilot = false;
  std::vector<std::string> look_alikes;
};

// Reads `db_path` without writing (a missing file means State::none). Throws InputError for an
// empty participant id or a file that is not an intact ModalStudy database.
ParticipantStatus participant_status(const std::string& db_path, const std::string& study,
                                     const std::string& participant);

// One line for people, e.g. "P07 finished this study on 2026-12-01 (19/19 trials)" or
// "P07 has an unfinished session (7/19 trials answered)"; "" for State::none.
std::string describe(const ParticipantStatus& status);

}  // namespace ms
