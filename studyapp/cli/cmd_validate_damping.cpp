// modalstudy validate-damping --material ID [--sounds 1,2,5,10,20,40] [--resamples N] [--seed N]
//                             [--snr-db DB] [--json] [--plot FIG.png|svg]
// Sterling et al. 2019's synthetic validation (Fig. 1.12) for one library material's Rayleigh law:
// strikes rendered and extracted, the law fitted from 1..N of them by each estimator, the median
// relative error of alpha1 and alpha2 per number of sounds (analysis/damping/synthetic_validation.hpp).
// JSON: {"material", "truth": {"alpha1", "alpha2"}, "sound_counts": [...], "resamples",
//        "estimators": [{"name", "alpha1_median_rel_error": [...], "alpha2_median_rel_error": [...]}]}.
// --plot FIG.png writes the figure's two panels, FIG-alpha1.png and FIG-alpha2.png.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "analysis/damping/synthetic_validation.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "studyapp/plots/plots.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/material.hpp"

namespace ms::cli {
namespace {

// FIG.png -> FIG-alpha1.png.
std::string panel_path(const std::string& path, const std::string& parameter) {
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "-" + parameter + p.extension().string())).string();
}

void draw_panel(const std::string& path, const SyntheticValidation& v, bool alpha1, const std::string& material) {
  std::vector<plots::Series> series;
  for (const auto& c : v.curves) {
    plots::Series s{c.estimator.name, {}};
    const auto& errors = alpha1 ? c.alpha1_median_rel_error : c.alpha2_median_rel_error;
    for (std::size_t i = 0; i < v.sound_counts.size(); ++i) s.points.push_back({double(v.sound_counts[i]), 100 * errors[i]});
    series.push_back(std::move(s));
  }
  plots::PlotOptions po;
  po.title = "Synthetic validation, " + material + ": " + (alpha1 ? "alpha1" : "alpha2");
  po.x_label = "Number of sounds";
  po.y_label = std::string("Median relative error of ") + (alpha1 ? "alpha1" : "alpha2") + " [%]";
  plots::line_plot(path, series, po, /*log_x=*/true);
}

}  // namespace

void register_validate_damping(CLI::App& app) {
  struct Options {
    std::string material, plot;
    std::vector<std::size_t> sounds{1, 2, 5, 10, 20, 40};
    std::size_t resamples = 30;
    std::uint64_t seed = 2019;
    double snr_db = 40;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "validate-damping", "Synthetic validation of the damping estimators (Sterling 2019, Fig. 1.12)");
  cmd->add_option("--material", opt->material, "Library material id (see `modalstudy materials`)")->required();
  cmd->add_option("--sounds", opt->sounds, "Numbers of sounds per estimate, comma separated")
      ->delimiter(',')
      ->check(CLI::Range(std::size_t{1}, std::size_t{400}));
  cmd->add_option("--resamples", opt->resamples, "Draws of that many sounds from the pool, per number")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000}));
  cmd->add_option("--seed", opt->seed, "Seed of the pool of strikes");
  cmd->add_option("--snr-db", opt->snr_db, "Noise below each strike's mean power [dB]")->check(CLI::Range(0.0, 200.0));
  cmd->add_option("--plot", opt->plot, "Draw the two panels: FIG.png or FIG.svg (writes FIG-alpha1, FIG-alpha2)");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt] {
    if (!opt->plot.empty()) plots::check_output_path(opt->plot);
    const Material* material = find_material(opt->material);
    if (!material) throw InputError(SourceLocation{}, "--material: unknown material '" + opt->material + "'");
    SyntheticValidationOptions options;
    options.sound_counts = opt->sounds;
    options.resamples = opt->resamples;
    options.seed = opt->seed;
    options.strikes.snr_db = opt->snr_db;
    const SyntheticValidation v = run_synthetic_validation(material->rayleigh, options);
    if (!opt->plot.empty()) {
      draw_panel(panel_path(opt->plot, "alpha1"), v, true, opt->material);
      draw_panel(panel_path(opt->plot, "alpha2"), v, false, opt->material);
    }
    if (opt->json) {
      nlohmann::json estimators = nlohmann::json::array();
      for (const auto& c : v.curves)
        estimators.push_back({{"name", c.estimator.name},
                              {"alpha1_median_rel_error", c.alpha1_median_rel_error},
                              {"alpha2_median_rel_error", c.alpha2_median_rel_error}});
      std::cout << nlohmann::json{{"material", opt->material},
                                  {"truth", {{"alpha1", v.truth.alpha1}, {"alpha2", v.truth.alpha2}}},
                                  {"sound_counts", v.sound_counts},
                                  {"resamples", opt->resamples},
                                  {"estimators", estimators}}
                       .dump()
                << "\n";
      return;
    }
    std::printf("Synthetic validation of %s (alpha1 %s 1/s, alpha2 %s s): median relative error over %zu resamples\n",
                opt->material.c_str(), format_g(v.truth.alpha1, 4).c_str(), format_g(v.truth.alpha2, 4).c_str(),
                opt->resamples);
    std::printf("%-14s %-8s", "estimator", "param");
    for (std::size_t n : v.sound_counts) std::printf(" %8zu", n);
    std::printf("   (sounds)\n");
    for (const auto& c : v.curves)
      for (int p = 0; p < 2; ++p) {
        std::printf("%-14s %-8s", p == 0 ? c.estimator.name.c_str() : "", p == 0 ? "alpha1" : "alpha2");
        for (double e : p == 0 ? c.alpha1_median_rel_error : c.alpha2_median_rel_error) std::printf(" %7.2f%%", 100 * e);
        std::printf("\n");
      }
  });
}

}  // namespace ms::cli
