// The command line of `studyapp` (DESIGN.md §5): options, the headless autopilot run, and the protocol
// check that ends a bad start with every problem on stderr and exit code 2 — all without Qt widgets.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace ms::gui {

struct AppOptions {
  std::string protocol_path;              // "" = choose on the start page
  std::string participant;
  std::string db_path;                    // "" = <protocol dir>/results/<study>.sqlite
  std::string cache_dir;                  // "" = default_cache_dir()
  std::string audio = "default";          // default | null | a device description
  bool allow_outside = false;
  bool new_session = false;               // --new-session: run a participant who finished once more
  std::optional<std::uint64_t> autopilot_seed;
  std::string experimenter_db;            // --experimenter DB: open the experimenter view only
};

// Parses argv. Returns an exit code when the program should stop now (--help, a bad option).
std::optional<int> parse_command_line(int argc, char** argv, AppOptions& options);

// Prints every problem of the protocol as "studyapp: PROBLEM" on stderr; true when there are none.
bool report_protocol_problems(const AppOptions& options);

// With --participant: true (after one line on stderr) for a participant who finished the study and no
// --new-session, or a results file that cannot be read; prints look-alike id warnings. A session
// another process holds is refused when the window opens it (Session throws SessionInUse).
bool report_participant_refusal(const AppOptions& options);

// `--autopilot SEED`: runs the simulated listener headless and prints a summary; returns the exit code.
int run_autopilot_command(const AppOptions& options);

// The stimulus cache used when none is given: $XDG_CACHE_HOME/modalstudy/stimuli (~/.cache/...). Files
// are named by recipe hash, so every protocol can share it; "" (memory only) without a home folder.
std::string default_cache_dir();

}  // namespace ms::gui
