// What the experimenter view lists: every session of a results database with its participant and how
// far it got (answered of scheduled trials). Read-only; the file is checked by ResultsStore first.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ms::gui {

struct SessionSummary {
  std::string study, participant;
  std::int64_t session = 0;
  std::int64_t started_ms = 0;
  std::optional<std::int64_t> finished_ms;
  std::int64_t answered = 0, scheduled = 0;
};

// Throws ms::InputError naming the file when it is not a ModalStudy database.
std::vector<SessionSummary> session_overview(const std::string& db_path);

}  // namespace ms::gui
