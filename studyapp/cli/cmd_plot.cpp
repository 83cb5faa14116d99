// modalstudy plot masking MODES.csv -o FILE | damping FEATURES.csv --law L -o FILE (and demo, lines in
// their own files): pictures (PNG or SVG by extension) through studyapp/plots, from real data.
#include <algorithm>
#include <filesystem>
#include <iostream>

#include "analysis/damping/damping_features.hpp"
#include "analysis/damping/damping_fit.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/fittable_law.hpp"
#include "studyapp/cli/plot_pictures.hpp"
#include "studyapp/cli/prune_csv.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "studyapp/plots/plots.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/masking_pruning.hpp"
#include "synthesis/modes_csv.hpp"
#include "studyapp/cli/plot_commands.hpp"

namespace ms::cli {

namespace fs = std::filesystem;
using plots::PlotOptions;

void register_plot(CLI::App& app) {
  struct Options {
    std::string modes, features, law, output, threshold_db, playback_db;
    bool linear = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("plot", "Draw pictures (PNG or SVG, by the output's extension)");
  cmd->require_subcommand(1);

  register_plot_demo(*cmd);

  CLI::App* masking_cmd = cmd->add_subcommand(
      "masking", "Mode levels (kept / dropped by masking), masking threshold and threshold in quiet");
  masking_cmd->add_option("modes", opt->modes, "Modes CSV (freq_hz,decay_per_s,amp)")->required();
  masking_cmd->add_option("-o,--output", opt->output, "Picture: .png or .svg")->required();
  masking_cmd->add_option("--threshold-db", opt->threshold_db, "Masking threshold a_v [dB], default 16")
      ->type_name("A");
  masking_cmd->add_option("--playback-db", opt->playback_db, "Playback level [dB SPL], default 70")->type_name("L");
  masking_cmd->callback([opt] {
    plots::check_output_path(opt->output);  // before reading anything
    PruneOptions o;
    auto option_error = [&](const std::string& problem) { return InputError(SourceLocation{opt->modes, 0, 0}, problem); };
    try {
      if (!opt->threshold_db.empty()) o.threshold_db = parse_number(opt->threshold_db, "--threshold-db");
      if (!opt->playback_db.empty()) o.playback_db = parse_number(opt->playback_db, "--playback-db");
      validate_prune_options(o);
    } catch (const InputError& e) {
      throw option_error(e.problem());
    } catch (const PruneError& e) {
      std::string option = "--" + e.field();
      std::replace(option.begin(), option.end(), '_', '-');
      throw option_error(option + " " + e.problem());
    }
    const auto [model, r] = prune_modes_csv(opt->modes, o);
    const std::string name = fs::path(opt->modes).filename().string();
    plot_masking_model(model, r, opt->output,
                       "Masking: " + name + " (a_v = " + format_g(o.threshold_db, 3) + " dB, " +
                           format_g(o.playback_db, 3) + " dB SPL): " + std::to_string(r.kept.size()) + " of " +
                           std::to_string(model.modes.size()) + " modes kept");
    std::cout << "wrote " << opt->output << "\n";
  });

  CLI::App* damping_cmd =
      cmd->add_subcommand("damping", "Damping features (lambda, c = 2d) with lsq, lb and emg fits of a law");
  damping_cmd->add_option("features", opt->features, "Features CSV: sound,freq_hz,decay_per_s,amp")->required();
  damping_cmd->add_option("--law", opt->law, "rayleigh | powerlaw | hybrid")->required();
  damping_cmd->add_option("-o,--output", opt->output, "Picture: .png or .svg")->required();
  damping_cmd->add_flag("--linear", opt->linear, "Linear axes (default: log-log)");
  damping_cmd->callback([opt] {
    plots::check_output_path(opt->output);
    const DampingKind law = parse_fittable_law(opt->law);
    const auto features = read_damping_features_csv(opt->features);
    std::size_t needed = 0;
    for (auto e : {DampingEstimator::lsq, DampingEstimator::lb, DampingEstimator::emg})
      needed = std::max(needed, damping_fit_param_count(law, e));
    if (features.size() < needed)
      throw InputError(SourceLocation{opt->features, features.back().line, 0},
                       std::to_string(features.size()) + " features, but fitting the " + opt->law +
                           " law by emg needs at least " + std::to_string(needed));
    const auto points = damping_points(features);
    std::vector<double> lambda, c;
    for (const auto& p : points) {
      lambda.push_back(p.lambda_rad2_s2);
      c.push_back(p.c_per_s);
    }
    PlotOptions o;
    o.title = "Damping: " + opt->law + " law fitted to " + fs::path(opt->features).filename().string() + " (" +
              std::to_string(points.size()) + " modes)";
    plots::damping_scatter(opt->output, lambda, c, fitted_curves(points, law), o, !opt->linear);
    std::cout << "wrote " << opt->output << "\n";
  });

  register_plot_lines(*cmd);
}

}  // namespace ms::cli
