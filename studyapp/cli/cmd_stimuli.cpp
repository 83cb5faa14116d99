// modalstudy stimuli build PARAMSET_OR_DIR... -o OUTDIR [--jobs N] [--json]
#include <nlohmann/json.hpp>

#include <iostream>
#include <thread>

#include "studyapp/cli/commands.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/stimulus_build.hpp"

namespace ms::cli {

void register_stimuli(CLI::App& app) {
  struct Options {
    std::vector<std::string> inputs;
    std::string out_dir;
    unsigned jobs = 0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* group = app.add_subcommand("stimuli", "Render and manage stimulus folders");
  group->require_subcommand(1);
  CLI::App* cmd = group->add_subcommand(
      "build", "Render parameter sets (files or folders) into OUTDIR with manifest.json; only what changed");
  cmd->add_option("inputs", opt->inputs, "Parameter sets or folders of them")->required();
  cmd->add_option("-o,--output", opt->out_dir, "Output folder")->required();
  cmd->add_option("-j,--jobs", opt->jobs, "Rendering threads (default: all cores)");
  cmd->add_flag("--json", opt->json, "Print one JSON object describing the build");
  cmd->callback([opt] {
    const unsigned threads = opt->jobs ? opt->jobs : std::max(1u, std::thread::hardware_concurrency());
    std::vector<std::string> errors;
    BuildReport report;
    try {
      report = build_stimuli(opt->inputs, opt->out_dir, threads, &errors);
    } catch (const InputError&) {
      // Every problem on its own line; the last line is the one the caller reports.
      for (std::size_t i = 0; i + 1 < errors.size(); ++i) std::cerr << "modalstudy: " << errors[i] << "\n";
      if (!errors.empty()) throw InputError(errors.back());
      throw;
    }
    if (opt->json) {
      nlohmann::json j = {{"output", opt->out_dir}, {"rendered", report.rendered}, {"reused", report.reused},
                          {"threads", report.threads}, {"seconds", report.seconds},
                          {"stimuli", nlohmann::json::array()}};
      for (const auto& e : report.entries)
        j["stimuli"].push_back({{"name", e.name}, {"source", e.source}, {"sha256", e.sha256},
                                {"recipe_hash", e.recipe_hash}, {"rendered", e.rendered},
                                {"warnings", e.warnings}});
      std::cout << j.dump() << "\n";
      return;
    }
    for (const auto& e : report.entries)
      for (const auto& w : e.warnings) std::cerr << "warning: " << e.source << ": " << w << "\n";
    std::cout << "rendered " << report.rendered << ", up to date " << report.reused << " ("
              << report.threads << " threads, " << report.seconds << " s)\n"
              << "stimuli in " << opt->out_dir << "/ (manifest: " << opt->out_dir << "/manifest.json)\n";
  });
}

}  // namespace ms::cli
