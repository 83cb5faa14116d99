// modalstudy plot demo -o DIR | masking MODES.csv -o FILE | damping FEATURES.csv --law L -o FILE:
// pictures (PNG or SVG by extension) through studyapp/plots, from built-in examples or real data.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <numbers>
#include <random>

#include "studyapp/cli/fittable_law.hpp"
#include "analysis/damping_features.hpp"
#include "analysis/damping_fit.hpp"
#include "analysis/emg_likelihood.hpp"
#include "analysis/tidy_csv.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/prune_csv.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "studyapp/plots/plots.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/masking_pruning.hpp"
#include "synthesis/modes_csv.hpp"

namespace ms::cli {

namespace {

namespace fs = std::filesystem;
using plots::PlotOptions;
using plots::Series;
using plots::XY;


// The law c(lambda) sampled log-uniformly over [lo, hi], for drawing.
std::vector<XY> sample_law(const DampingLaw& law, double lo, double hi, int n = 200) {
  std::vector<XY> out;
  for (int i = 0; i < n; ++i) {
    const double lambda = lo * std::pow(hi / lo, double(i) / (n - 1));
    out.push_back({lambda, damping_c_per_s(law, lambda)});
  }
  return out;
}

// "%.2g" without the exponent's sign and zero padding (9.6e-06 -> 9.6e-6): legends stay short.
std::string short_g(double v) {
  std::string s = format_g(v, 2);
  const auto e = s.find('e');
  if (e == std::string::npos) return s;
  std::string exponent = s.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  return s.substr(0, e) + "e" + (negative ? "-" : "") + (exponent.empty() ? "0" : exponent);
}

std::string law_summary(const DampingFit& fit) {
  std::string s = to_string(fit.estimator) + ":";
  if (fit.law.kind != DampingKind::powerlaw) s += " α₁=" + short_g(fit.law.alpha1);
  s += " α₂=" + short_g(fit.law.alpha2);
  if (fit.law.kind != DampingKind::rayleigh) s += " α₃=" + short_g(fit.law.alpha3);
  return s;
}

// lsq, lb and emg fits of one law to the points, as curves over the data's lambda range.
std::vector<Series> fitted_curves(const std::vector<DampingPoint>& points, DampingKind law) {
  double lo = points.front().lambda_rad2_s2, hi = lo;
  for (const auto& p : points) {
    lo = std::min(lo, p.lambda_rad2_s2);
    hi = std::max(hi, p.lambda_rad2_s2);
  }
  if (hi <= lo) hi = lo * 1.01;
  std::vector<Series> curves;
  for (auto estimator : {DampingEstimator::lsq, DampingEstimator::lb, DampingEstimator::emg}) {
    const DampingFit fit = fit_damping(points, law, estimator);
    curves.push_back({law_summary(fit), sample_law(fit.law, lo, hi)});
  }
  return curves;
}

void plot_masking_model(const ModalModel& model, const PruneResult& r, const std::string& output,
                        const std::string& title) {
  std::vector<double> freq_hz;
  std::vector<bool> kept(model.modes.size(), false);
  for (const auto& m : model.modes) freq_hz.push_back(m.freq_hz);
  for (std::size_t k : r.kept) kept[k] = true;
  PlotOptions o;
  o.title = title;
  plots::masking_plot(output, freq_hz, r.level_db, r.masking_db, r.quiet_db, kept, o);
}

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

void register_plot(CLI::App& app) {
  struct Options {
    std::string dir, format = "png", modes, features, law, output, threshold_db, playback_db;
    bool linear = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("plot", "Draw pictures (PNG or SVG, by the output's extension)");
  cmd->require_subcommand(1);

  CLI::App* demo_cmd = cmd->add_subcommand("demo", "Draw one example of every plot kind from built-in data");
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

  // Lines from tidy data, e.g. perceived difference vs number of modes, one line per method: the
  // mean of y at each x per series (several listeners' rows average).
  struct LineOptions {
    std::string data, x, y, series, output, title, x_label, y_label;
    bool log_x = false;
  };
  auto lo = std::make_shared<LineOptions>();
  CLI::App* lines_cmd = cmd->add_subcommand(
      "lines", "Mean of a column against another from tidy CSV, one line per series (e.g. difference vs modes)");
  lines_cmd->add_option("data", lo->data, "Tidy CSV")->required();
  lines_cmd->add_option("--x", lo->x, "Column on the x axis (numeric)")->required();
  lines_cmd->add_option("--y", lo->y, "Column averaged on the y axis (numeric)")->required();
  lines_cmd->add_option("--series", lo->series, "Column naming the lines (default: one line)");
  lines_cmd->add_option("-o,--output", lo->output, "Picture: .png or .svg")->required();
  lines_cmd->add_option("--title", lo->title, "Title (default: y vs x)");
  lines_cmd->add_option("--x-label", lo->x_label, "x-axis label with unit (default: the column)");
  lines_cmd->add_option("--y-label", lo->y_label, "y-axis label with unit (default: the column)");
  lines_cmd->add_flag("--log-x", lo->log_x, "Logarithmic x axis");
  lines_cmd->callback([lo] {
    plots::check_output_path(lo->output);
    const TidyCsv table = TidyCsv::read(lo->data);
    if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
    const std::size_t cx = table.column(lo->x), cy = table.column(lo->y);
    const bool by_series = !lo->series.empty();
    const std::size_t cs = by_series ? table.column(lo->series) : 0;
    std::vector<std::string> order;
    std::map<std::string, std::map<double, std::pair<double, int>>> sums;  // series -> x -> (sum y, n)
    for (std::size_t r = 0; r < table.rows(); ++r) {
      const std::string name = by_series ? table.cell(r, cs) : lo->y;
      if (!sums.count(name)) order.push_back(name);
      auto& cell = sums[name][table.number(r, cx)];
      cell.first += table.number(r, cy);
      cell.second += 1;
    }
    std::vector<plots::Series> series;
    for (const auto& name : order) {
      plots::Series s{name, {}};
      for (const auto& [x, acc] : sums[name]) s.points.push_back({x, acc.first / acc.second});
      series.push_back(std::move(s));
    }
    PlotOptions o;
    o.title = lo->title.empty() ? lo->y + " vs " + lo->x : lo->title;
    o.x_label = lo->x_label.empty() ? lo->x : lo->x_label;
    o.y_label = lo->y_label.empty() ? lo->y : lo->y_label;
    plots::line_plot(lo->output, series, o, lo->log_x);
    std::cout << "wrote " << lo->output << "\n";
  });
}

}  // namespace ms::cli
