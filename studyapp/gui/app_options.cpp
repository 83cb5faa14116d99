// studyapp's command line: CLI11 options, the protocol check and the headless autopilot.
#include "studyapp/gui/app_options.hpp"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/participant_status.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "synthesis/input_error.hpp"

namespace ms::gui {

std::optional<int> parse_command_line(int argc, char** argv, AppOptions& options) {
  CLI::App app{"studyapp: run a listening test from a protocol file (ModalStudy)"};
  app.set_version_flag("--version", "studyapp 0.1.0");
  app.add_option("protocol", options.protocol_path, "Protocol file (protocols/*.yaml); omit to choose in the window");
  app.add_option("--participant", options.participant, "Participant id (e.g. P07)");
  app.add_option("--db", options.db_path, "Results database: a file (default <protocol dir>/results/<study>.sqlite)"
                 " or a postgresql://user@host:port/dbname URI");
  app.add_option("--cache", options.cache_dir, "Rendered-stimulus cache folder (default ~/.cache/modalstudy/stimuli)");
  app.add_option("--audio", options.audio, "Audio output: default, null (no sound, events still logged) or a device name")
      ->capture_default_str();
  app.add_flag("--allow-outside", options.allow_outside, "Allow stimulus files outside the protocol's and stimuli/ folders");
  app.add_flag("--new-session", options.new_session, "Run a participant who already finished the study once more");
  app.add_option("--autopilot", options.autopilot_seed, "Answer every trial with the simulated listener (headless), seeded");
  app.add_option("--experimenter", options.experimenter_db, "Open the experimenter view of a results database");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (options.autopilot_seed && options.protocol_path.empty()) {
    std::cerr << "studyapp: --autopilot needs a protocol file\n";
    return 2;
  }
  return std::nullopt;
}

bool report_protocol_problems(const AppOptions& options) {
  ValidateOptions validate;
  validate.allow_outside = options.allow_outside;
  const ProtocolCheck check = check_protocol_file(options.protocol_path, validate);
  for (const std::string& p : check.problems) std::cerr << "studyapp: " << p << "\n";
  return check.problems.empty() && check.protocol.has_value();
}

bool report_participant_refusal(const AppOptions& options) {
  if (options.participant.empty() || options.protocol_path.empty()) return false;
  try {
    const Protocol protocol = load_protocol(options.protocol_path);
    const std::string db = options.db_path.empty() ? default_db_path(options.protocol_path, protocol.study) : options.db_path;
    const ParticipantStatus status = participant_status(db, protocol.study, options.participant);
    for (const auto& other : status.look_alikes)
      std::cerr << "studyapp: warning: participant id '" << status.participant << "' differs only by case or spaces from '"
                << other << "', who is already in " << db << "\n";
    if (status.state == ParticipantStatus::State::finished && !options.new_session) {
      std::cerr << "studyapp: " << describe(status) << "; use --new-session to run it again\n";
      return true;
    }
  } catch (const InputError& e) {
    std::cerr << "studyapp: " << e.what() << "\n";
    return true;
  }
  return false;
}

int run_autopilot_command(const AppOptions& options) {
  AutopilotOptions a;
  a.protocol_path = options.protocol_path;
  if (!options.participant.empty()) a.participant = options.participant;
  a.db_path = options.db_path;
  a.cache_dir = options.cache_dir.empty() ? default_cache_dir() : options.cache_dir;
  a.seed = *options.autopilot_seed;
  a.allow_outside = options.allow_outside;
  a.new_session = options.new_session;
  try {
    const AutopilotSummary s = run_autopilot(a);
    for (const auto& w : s.warnings) std::cerr << "studyapp: warning: " << w << "\n";
    std::cout << "studyapp: autopilot " << (s.resumed ? "resumed" : "ran") << " session " << s.session << ": answered "
              << s.answered_now << " trials now, " << (s.finished ? "finished" : "not finished") << " (" << s.total
              << " trials)\nresults: " << s.db_path << "\n";
    return 0;
  } catch (const InvalidProtocol& e) {
    for (const std::string& p : e.problems()) std::cerr << "studyapp: " << p << "\n";
    return 2;
  } catch (const InputError& e) {
    std::cerr << "studyapp: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "studyapp: error: " << e.what() << "\n";
    return 3;
  }
}

std::string default_cache_dir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  std::filesystem::path base;
  if (xdg && *xdg) base = xdg;
  else if (home && *home) base = std::filesystem::path(home) / ".cache";
  else return {};
  return (base / "modalstudy" / "stimuli").string();
}

}  // namespace ms::gui
