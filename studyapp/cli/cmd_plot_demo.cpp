// modalstudy plot demo -o DIR [--format png|svg]: one example of every plot kind from built-in data.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <numbers>
#include <random>

#include "analysis/damping/damping_features.hpp"
#include "analysis/damping/damping_fit.hpp"
#include "synthesis/tidy_csv.hpp"
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

namespace {

namespace fs = std::filesystem;
using plots::PlotOptions;
using plots::Series;
using plots::XY;

// ---- built-in examples: made-up but plausible numbers, fixed seeds (same pictures with one std library) ----

void demo(const std::string& dir, const std::string& ext) {
  auto out = [&](const std::string& name) { return (fs::path(dir) / (name + ext)).string(); };

  // 1. MDS map of eight materials, with a model's map that is rotated, reflected, scaled and a bit off.
  const std::vector<std::string> materials = {"glass",  "porcelain", "steel",   "aluminium",
                                              "brass",  "oak",       "plastic", "ceramic"};
  const std::vector<XY> listeners = {{-0.55, 0.42}, {-0.38, 0.55}, {0.62, 0.30}, {0.48, 0.05},
                                     {0.70, -0.12}, {-0.30, -0.62}, {-0.05, -0.48}, {-0.52, 0.12}};
  std::vector<XY> model;
  for (std::size_t i = 0; i < listeners.size(); ++i) {
    const double x = listeners[i].x + 0.06 * std::sin(3.0 * double(i)), y = listeners[i].y + 0.06 * std::cos(5.0 * double(i));
    model.push_back({2.0 * (0.5 * x + 0.866 * y) + 1.0, 2.0 * (0.866 * x - 0.5 * y) - 0.5});
  }
  PlotOptions o;
  o.title = "Perceptual map of struck materials (MDS, 2 dimensions)";
  plots::MapOverlay overlay;
  overlay.points = model;
  overlay.name = "model";
  overlay.base_name = "listeners";
  plots::mds_map(out("mds_map"), listeners, materials, o, overlay);

  // 2. Identification of five materials (rows: presented; each row sums to 100 %).
  o = {};
  o.title = "Material identification (24 listeners × 10 presentations)";
  plots::confusion_heatmap(out("confusion_heatmap"), {"glass", "metal", "wood", "plastic", "ceramic"},
                           {{71.3, 12.5, 0.4, 2.1, 13.7},
                            {9.2, 85.8, 0.0, 1.3, 3.7},
                            {0.8, 0.4, 78.3, 17.1, 3.3},
                            {2.5, 1.7, 22.9, 66.7, 6.2},
                            {20.4, 5.0, 2.9, 8.3, 63.3}},
                           o);

  // 3. MUSHRA: 12 listeners rate six versions of a struck plate.
  const std::vector<std::string> conditions = {"hidden ref.", "all modes", "masking 16 dB", "top 20", "top 5",
                                               "anchor"};
  const std::vector<double> centre = {96, 90, 84, 63, 31, 18}, spread = {4, 7, 9, 13, 12, 9};
  std::mt19937 rng(4);
  std::vector<std::vector<double>> ratings(conditions.size());
  std::vector<double> means, lo, hi;
  for (std::size_t c = 0; c < conditions.size(); ++c) {
    std::normal_distribution<double> d(centre[c], spread[c]);
    double sum = 0, sum2 = 0;
    for (int l = 0; l < 12; ++l) {
      const double r = std::clamp(std::round(d(rng)), 0.0, 100.0);
      ratings[c].push_back(r);
      sum += r;
      sum2 += r * r;
    }
    const double n = 12, mean = sum / n, sd = std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1)));
    const double half = 2.201 * sd / std::sqrt(n);  // t(0.975, 11 df)
    means.push_back(mean);
    lo.push_back(mean - half);
    hi.push_back(mean + half);
  }
  o = {};
  o.title = "MUSHRA: struck glass plate, 12 listeners";
  plots::mushra_boxplot(out("mushra_boxplot"), conditions, ratings, means, lo, hi, o);

  // 4. Perceived difference from the full model as modes are added in progressive order.
  const std::vector<double> counts = {1, 2, 5, 10, 20, 50, 100, 200};
  const std::vector<double> plate = {88, 79, 61, 42, 27, 12, 6, 4}, bar = {72, 55, 30, 14, 8, 5, 4, 3};
  std::vector<Series> series(2);
  series[0].name = "glass plate (energy order)";
  series[1].name = "steel bar (energy order)";
  for (std::size_t i = 0; i < counts.size(); ++i) {
    series[0].points.push_back({counts[i], plate[i]});
    series[1].points.push_back({counts[i], bar[i]});
  }
  o = {};
  o.title = "Perceived difference vs number of modes";
  o.x_label = "Number of modes synthesized (log scale)";
  o.y_label = "Perceived difference from all modes (0–100)";
  plots::line_plot(out("line_plot"), series, o, true);

  // 5. Damping of 3 strikes of a hybrid-law material with one-sided support damping, and its fits.
  const DampingLaw truth{DampingKind::hybrid, 6.0, 2.0e-6, 0.7, 0.0};
  std::mt19937 rng2(7);
  std::uniform_real_distribution<double> freq_log(std::log(200.0), std::log(12000.0));
  std::exponential_distribution<double> support(1.0 / 4.0);  // mean 4 1/s extra c
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<DampingPoint> points;
  for (int i = 0; i < 90; ++i) {
    const double omega = 2 * std::numbers::pi * std::exp(freq_log(rng2)), lambda = omega * omega;
    points.push_back({lambda, std::max(0.5, damping_c_per_s(truth, lambda) + support(rng2) + noise(rng2))});
  }
  std::vector<double> lambda, c;
  for (const auto& p : points) {
    lambda.push_back(p.lambda_rad2_s2);
    c.push_back(p.c_per_s);
  }
  o = {};
  o.title = "Hybrid damping law fitted to 90 modes of 3 strikes";
  plots::damping_scatter(out("damping_scatter"), lambda, c, fitted_curves(points, DampingKind::hybrid), o, true);

  // 6. Masking of a 40-mode plate-like model at 70 dB SPL, a_v = 16 dB.
  ModalModel plate_model;
  // 30 modes, plus a weak neighbour 3 % above every third one: those the masking rule removes.
  for (int k = 1; k <= 30; ++k) {
    const double f = 150.0 * std::pow(double(k), 1.25) * (1 + 0.03 * std::sin(7.0 * k));
    const double amp = std::pow(double(k), -0.9) * (0.3 + 0.7 * std::abs(std::cos(2.3 * k)));
    plate_model.modes.push_back({f, 3.0 + 2.5e-4 * f, amp, 0});
    if (k % 3 == 0) plate_model.modes.push_back({1.03 * f, 3.0 + 2.5e-4 * f, 0.08 * amp, 0});
  }
  PruneOptions prune;
  const PruneResult r = prune_modes(plate_model, prune);
  plot_masking_model(plate_model, r, out("masking_plot"),
                     "Masking: 40-mode plate at 70 dB SPL, a_v = 16 dB: " + std::to_string(r.kept.size()) +
                         " of 40 modes kept");
}

}  // namespace

void register_plot_demo(CLI::App& group) {
  struct Options {
    std::string dir, format = "png";
  };
  auto opt = std::make_shared<Options>();
  CLI::App* demo_cmd = group.add_subcommand("demo", "Draw one example of every plot kind from built-in data");
  demo_cmd->add_option("-o,--output", opt->dir, "Folder for the pictures (created if missing)")->required();
  demo_cmd->add_option("--format", opt->format, "png (default) | svg");
  demo_cmd->callback([opt] {
    if (opt->format != "png" && opt->format != "svg")
      throw InputError("--format: expected png or svg, got '" + opt->format + "'");
    std::error_code ec;
    fs::create_directories(opt->dir, ec);
    if (!fs::is_directory(opt->dir, ec))
      throw InputError(SourceLocation{opt->dir, 0, 0}, "cannot create the output folder" +
                                                           (ec ? " (" + ec.message() + ")" : std::string()));
    demo(opt->dir, "." + opt->format);
    std::cout << "wrote 6 pictures to " << opt->dir << " (mds_map, confusion_heatmap, mushra_boxplot, line_plot, "
              << "damping_scatter, masking_plot)." << opt->format << "\n";
  });
}

}  // namespace ms::cli
