// modalstudy protocol check PROTOCOL.yaml [--allow-outside] [--json]
// modalstudy protocol schedule PROTOCOL.yaml --participant ID [--json]
// modalstudy protocol import-webmushra CONFIG.yaml -o PROTOCOL.yaml [--json]
// Validates a study protocol (every problem, one line each, exit 2), prints a participant's trials, or
// turns a webMUSHRA experiment config into a protocol.
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <iostream>

#include "studyapp/cli/commands.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/schedule.hpp"
#include "studyapp/core/webmushra_import.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms::cli {

namespace {

struct ProtocolOptions {
  std::string file, participant, output;
  bool allow_outside = false, json = false;
};

// Problems end the command with exit 2 (like every other bad input), after all were printed.
[[noreturn]] void exit_problems() { std::exit(2); }

void run_check(const ProtocolOptions& o) {
  ValidateOptions vo;
  vo.allow_outside = o.allow_outside;
  const ProtocolCheck c = check_protocol_file(o.file, vo);
  if (o.json) {
    nlohmann::json j;
    j["problems"] = c.problems;
    j["warnings"] = c.warnings;
    j["blocks"] = c.protocol ? c.protocol->blocks.size() : 0;
    j["stimuli"] = c.protocol ? c.protocol->stimuli.size() : 0;
    std::cout << j.dump(2) << "\n";
  } else {
    for (const auto& p : c.problems) std::cerr << p << "\n";
    for (const auto& w : c.warnings) std::cerr << w << "\n";
    if (c.problems.empty())
      std::cout << o.file << ": OK (" << c.protocol->blocks.size() << " blocks, " << c.protocol->stimuli.size()
                << " stimuli)\n";
  }
  std::cout.flush();
  if (!c.problems.empty()) exit_problems();
}

void run_schedule(const ProtocolOptions& o) {
  ValidateOptions vo;
  vo.load_paramsets = false;  // scheduling needs names, not rendered sets
  const ProtocolCheck c = check_protocol_file(o.file, vo);
  if (!c.problems.empty()) {
    for (const auto& p : c.problems) std::cerr << p << "\n";
    exit_problems();
  }
  const Schedule s = make_schedule(*c.protocol, o.participant);
  if (o.json) {
    nlohmann::json j;
    j["participant"] = s.participant;
    j["seed"] = s.seed;
    j["block_order"] = s.block_order;
    j["trials"] = nlohmann::json::array();
    for (const auto& t : s.trials)
      j["trials"].push_back({{"block", t.block}, {"block_id", t.block_id}, {"type", to_string(t.type)},
                             {"index", t.index}, {"repeat", t.repeat}, {"training", t.training},
                             {"break_after", t.break_after}, {"stimuli", t.stimuli},
                             {"reference", t.reference}, {"swapped", t.swapped}});
    std::cout << j.dump(2) << "\n";
    return;
  }
  for (const auto& t : s.trials) {
    std::cout << t.block_id << " #" << t.index << " " << to_string(t.type) << (t.training ? " [training]" : "");
    if (!t.reference.empty()) std::cout << " ref=" << t.reference;
    std::cout << ":";
    for (const auto& n : t.stimuli) std::cout << " " << n;
    std::cout << (t.break_after ? "  | break" : "") << "\n";
  }
}

// What could not be carried over goes to stderr, one line each; the protocol is written only once it
// parses and validates.
void run_import_webmushra(const ProtocolOptions& o) {
  const WebMushraImport imported = import_webmushra(o.file, o.output);
  write_file_atomically(o.output, imported.protocol_yaml);
  if (o.json) {
    std::cout << nlohmann::json{{"protocol", o.output}, {"notes", imported.notes}}.dump(2) << "\n";
    return;
  }
  for (const std::string& n : imported.notes) std::cerr << "note: " << n << "\n";
  std::cout << "wrote " << o.output << " (" << imported.notes.size() << " notes: what webMUSHRA does that it does not)\n";
}

}  // namespace

void register_protocol(CLI::App& app) {
  auto opts = std::make_shared<ProtocolOptions>();
  auto* cmd = app.add_subcommand("protocol", "Check a study protocol, print a participant's trial schedule, or import a "
                                             "webMUSHRA config");
  cmd->require_subcommand(1);
  auto* check = cmd->add_subcommand("check", "Report every problem of a protocol (exit 2 if any)");
  check->add_option("protocol", opts->file, "Protocol YAML")->required();
  check->add_flag("--allow-outside", opts->allow_outside, "Allow stimulus files outside the protocol's folder and stimuli/");
  check->add_flag("--json", opts->json, "Print {problems, blocks, stimuli} as JSON");
  check->callback([opts] { run_check(*opts); });
  auto* sched = cmd->add_subcommand("schedule", "Print the ordered trials of one participant");
  sched->add_option("protocol", opts->file, "Protocol YAML")->required();
  sched->add_option("--participant", opts->participant, "Participant id (seeds the order)")->required();
  sched->add_flag("--json", opts->json, "Print the schedule as JSON");
  sched->callback([opts] { run_schedule(*opts); });
  auto* wm = cmd->add_subcommand("import-webmushra", "Turn a webMUSHRA experiment config into a protocol");
  wm->add_option("config", opts->file, "webMUSHRA config YAML (audio paths relative to webMUSHRA's root folder)")
      ->required();
  wm->add_option("-o,--output", opts->output, "Protocol YAML to write (stimulus paths relative to it)")->required();
  wm->add_flag("--json", opts->json, "Print {protocol, notes} as JSON");
  wm->callback([opts] { run_import_webmushra(*opts); });
}

}  // namespace ms::cli
