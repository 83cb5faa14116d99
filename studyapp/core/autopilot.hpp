// Headless run of a whole session with the simulated listener (`studyapp --autopilot SEED`): renders
// the stimuli, opens or resumes the session, answers every remaining trial, logs the plays.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "synthesis/input_error.hpp"

namespace ms {

struct AutopilotOptions {
  std::string protocol_path;
  std::string participant = "autopilot";
  std::string db_path;         // "" = <protocol dir>/results/<study>.sqlite
  std::string cache_dir;       // "" = memory only
  std::uint64_t seed = 1;
  bool allow_outside = false;
  bool new_session = false;    // run a participant who finished once more
  std::size_t stop_after = 0;  // answer at most this many trials, then return (0 = all; for tests)
};

struct AutopilotSummary {
  std::string db_path;
  std::int64_t session = 0;
  bool resumed = false;
  std::size_t answered_now = 0, total = 0;
  bool finished = false;
  std::vector<std::string> warnings;  // see Session::warnings
};

// A protocol that does not validate: what() is the first problem (one line); problems() all of them.
class InvalidProtocol : public InputError {
 public:
  explicit InvalidProtocol(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

// Throws InvalidProtocol if the protocol does not validate, InputError for a stimulus that cannot be made.
AutopilotSummary run_autopilot(const AutopilotOptions& options,
                               const std::function<void(const std::string&)>& log = {});

// The default results database of a protocol: <protocol dir>/results/<study>.sqlite.
std::string default_db_path(const std::string& protocol_path, const std::string& study);

}  // namespace ms
