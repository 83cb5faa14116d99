// modalstudy audit-generate --seed S [--effects a,b] [--strength u,...] [--strikes N] -o DIR
// Synthetic "measured" strikes hiding the given effects (analysis/audit/hidden_effect_generator.hpp),
// to try the audit on data whose answer is known. Writes DIR/strikeN.wav and DIR/hidden.json.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <random>

#include "analysis/audit/hidden_effect_generator.hpp"
#include "studyapp/cli/commands.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms::cli {

void register_audit_generate(CLI::App& app) {
  struct Options {
    std::uint64_t seed = 1;
    std::vector<std::string> effects;
    std::vector<double> strengths;
    std::size_t strikes = 5;
    double duration_s = 1.5;
    double jitter_db = 0.0;
    std::string output;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("audit-generate", "Write synthetic strikes that hide known effects (for trying the audit)");
  cmd->add_option("--seed", opt->seed, "Seed of the object, strikes and effect strengths")->required();
  cmd->add_option("--effects", opt->effects, "Comma-separated effects to hide (default: none)")->delimiter(',');
  cmd->add_option("--strength", opt->strengths, "Strength in [0, 1] per effect (default: drawn from the seed)")
      ->delimiter(',');
  cmd->add_option("--strikes", opt->strikes, "Number of strikes (default 5)")->check(CLI::Range(1, 50));
  cmd->add_option("--duration-s", opt->duration_s, "Seconds per strike (default 1.5)")->check(CLI::Range(0.3, 30.0));
  cmd->add_option("--jitter-db", opt->jitter_db,
                  "Strikes that move: every mode's amplitude in every strike off by this many dB (standard "
                  "deviation, independent per mode and strike; default 0)")
      ->check(CLI::Range(0.0, 20.0));
  cmd->add_option("-o,--output", opt->output, "Folder for strikeN.wav and hidden.json")->required();
  cmd->callback([opt] {
    std::vector<double> strengths = opt->strengths;
    if (strengths.empty()) {
      std::mt19937_64 rng(opt->seed ^ 0x5eedULL);
      std::uniform_real_distribution<double> U(0.0, 1.0);
      for (std::size_t i = 0; i < opt->effects.size(); ++i) strengths.push_back(U(rng));
    }
    if (strengths.size() != opt->effects.size())
      throw InputError("--strength needs one value per effect (" + std::to_string(opt->effects.size()) + ")");
    audit::GeneratorOptions g;
    g.strikes = opt->strikes;
    g.duration_s = opt->duration_s;
    g.amplitude_jitter_db = opt->jitter_db;
    audit::HiddenCase hc;
    try {
      hc = audit::generate_hidden_case(opt->seed, opt->effects, strengths, g);
    } catch (const std::invalid_argument& e) {
      std::string known;
      for (const auto& n : audit::hideable_effects()) known += (known.empty() ? "" : ", ") + n;
      throw InputError(std::string("--effects: ") + e.what() + " (known: " + known + ")");
    }
    std::filesystem::create_directories(opt->output);
    const std::filesystem::path dir(opt->output);
    for (const auto& r : hc.recordings) {
      Audio a;
      a.sample_rate_hz = r.sample_rate_hz;
      a.samples = r.samples;
      write_wav((dir / (r.name + ".wav")).string(), a, SampleFormat::float32);
    }
    nlohmann::json j{{"seed", hc.seed}, {"effects", hc.effects}, {"strengths", hc.strengths},
                     {"strike_gain", hc.strike_gain}, {"summary", hc.summary}};
    write_file_atomically((dir / "hidden.json").string(), j.dump(2) + "\n");
    std::cout << hc.summary << "\nwrote " << hc.recordings.size() << " strikes to " << opt->output << "\n";
  });
}

}  // namespace ms::cli
