// modalstudy synth PARAMSET.yaml -o OUT.wav [--set key=value]... [--format F] [--allow-outside] [--json]
#include <nlohmann/json.hpp>

#include <iostream>

#include "studyapp/cli/commands.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/modes_csv.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/stimulus.hpp"

namespace ms::cli {

void register_synth(CLI::App& app) {
  struct Options {
    std::string paramset, output, format, modes_out;
    std::vector<std::string> sets;
    bool json = false, allow_outside = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("synth", "Render one parameter set to a WAV file");
  cmd->add_option("paramset", opt->paramset, "Parameter set (YAML)")->required();
  cmd->add_option("-o,--output", opt->output, "Output WAV file")->required();
  cmd->add_option("--set", opt->sets, "Override a key, e.g. --set excitation.contact_s=0.002");
  cmd->add_option("--format", opt->format, "float32 | pcm24 | pcm16 (default: the set's output.format)");
  cmd->add_option("--modes-out", opt->modes_out, "Also write the rendered modes as a modes CSV");
  cmd->add_flag("--allow-outside", opt->allow_outside,
                "Allow files the set names (a modes CSV) outside its folder and the project's stimuli/");
  cmd->add_flag("--json", opt->json, "Print one JSON object describing the result");
  cmd->callback([opt] {
    remove_temporaries_on_signals();  // Ctrl-C while a long render is written leaves no .tmp file
    const Confinement anywhere = Confinement::anywhere();
    ParamSet p = load_paramset(opt->paramset, opt->sets, opt->allow_outside ? &anywhere : nullptr);
    if (!opt->format.empty()) {
      p.format_where = SourceLocation{"--format", 0, 0};
      try {
        p.format = parse_sample_format(opt->format);
      } catch (const std::invalid_argument& e) {
        throw InputError(SourceLocation{"--format", 0, 0}, e.what());
      }
    }
    const RenderedStimulus r = render_stimulus(p);
    check_writable(p, r.audio, p.format_where);
    write_wav(opt->output, r.audio, p.format);
    if (!opt->modes_out.empty()) {
      std::vector<std::string> ignored;
      write_modes_csv(opt->modes_out, audible_model(p, ignored));
    }
    if (opt->json) {
      nlohmann::json j = {{"output", opt->output},       {"recipe_hash", p.recipe_hash},
                          {"sample_rate", p.sample_rate_hz}, {"frames", r.audio.frames()},
                          {"modes", r.modes_rendered},   {"level_gain", r.level_gain},
                          {"modes_before_pruning", p.modes_before_pruning},
                          {"format", to_string(p.format)}, {"warnings", r.warnings}};
      std::cout << j.dump() << "\n";
    } else {
      for (const auto& w : r.warnings) std::cerr << "warning: " << opt->paramset << ": " << w << "\n";
      std::cout << opt->output << ": " << r.modes_rendered << " modes, " << r.audio.frames()
                << " frames at " << p.sample_rate_hz << " Hz\n";
    }
  });
}

}  // namespace ms::cli
