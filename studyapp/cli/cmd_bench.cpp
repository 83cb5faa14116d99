// modalstudy bench synth --modes N --seconds S [--json]: resonator-bank throughput on one thread.
// Random modes (seeded) spread over 50 Hz - 16 kHz; best of several runs; mode-samples per second.
#include <nlohmann/json.hpp>

#include <chrono>
#include <iostream>
#include <random>

#include "studyapp/cli/commands.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/resonator_bank.hpp"

namespace ms::cli {

void register_bench(CLI::App& app) {
  struct Options {
    std::size_t modes = 1024;
    double seconds = 2.0;
    double sample_rate = 44100;
    int repeats = 5;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* group = app.add_subcommand("bench", "Measure throughput");
  group->require_subcommand(1);
  CLI::App* cmd = group->add_subcommand("synth", "Resonator-bank synthesis throughput (one thread)");
  cmd->add_option("--modes", opt->modes, "Number of modes")->check(CLI::Range(1, 1000000));
  cmd->add_option("--seconds", opt->seconds, "Seconds of audio per run")->check(CLI::Range(0.001, 600.0));
  cmd->add_option("--sample-rate", opt->sample_rate, "Sample rate [Hz]")->check(CLI::Range(8000.0, 384000.0));
  cmd->add_option("--repeats", opt->repeats, "Runs; the fastest counts")->check(CLI::Range(1, 100));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt] {
    ModalModel model;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> logf(std::log(50.0), std::log(16000.0));
    std::uniform_real_distribution<double> decay(0.5, 50.0), amp(0.1, 1.0);
    for (std::size_t i = 0; i < opt->modes; ++i)
      model.modes.push_back(Mode{std::exp(logf(rng)), decay(rng), amp(rng), 0.0});
    const std::size_t frames = std::size_t(opt->seconds * opt->sample_rate);
    std::vector<float> out(frames);
    double best = 1e300;
    for (int r = 0; r < opt->repeats; ++r) {
      ResonatorBank bank(model, Excitation{}, opt->sample_rate);
      const auto t0 = std::chrono::steady_clock::now();
      bank.render(out.data(), frames);
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      best = std::min(best, s);
    }
    const double rate = double(opt->modes) * double(frames) / best;
    if (opt->json) {
      std::cout << nlohmann::json{{"modes", opt->modes},     {"seconds", opt->seconds},
                                  {"sample_rate", opt->sample_rate}, {"threads", 1},
                                  {"mode_samples_per_s", rate}}.dump()
                << "\n";
    } else {
      std::cout << opt->modes << " modes x " << frames << " samples in " << best * 1e3 << " ms: "
                << rate << " mode-samples/s (" << rate / opt->sample_rate << " modes in real time)\n";
    }
  });
}

}  // namespace ms::cli
