// modalstudy fit-damping FEATURES.csv --law rayleigh|powerlaw|hybrid --estimator emg|lsq|lb [--json]
//                        [--noise constant|relative] [--plot-data OUT.csv]: fit a material damping law
//                        to per-mode features (--noise: emg's spread, see DampingFitOptions).
// JSON: {"law","estimator","noise","params":{...},"sigma","eta","loglik","iterations","seconds"}. Param keys:
// alpha = alpha1 [1/s], beta = alpha2, alpha3 = exponent (rayleigh: alpha, beta; powerlaw: beta, alpha3;
// hybrid: alpha, beta, alpha3), all for c = 2d with lambda in (rad/s)^2. sigma/eta/loglik are null for
// lsq and lb (they estimate no noise model). seconds = wall time of the fit alone (not of reading the CSV).
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "studyapp/cli/fittable_law.hpp"
#include "analysis/damping/damping_features.hpp"
#include "analysis/damping/damping_fit.hpp"
#include "analysis/damping/emg_likelihood.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/csv.hpp"
#include "synthesis/input_error.hpp"

namespace ms::cli {

namespace {

std::string format_g(double v) { return cli::format_g(v, 10); }

// Per point: the data, the fitted c and the residual, for plotting (sorted as in the input).
std::string plot_data_csv(const std::vector<DampingFeature>& features, const std::vector<DampingPoint>& points,
                          const DampingLaw& law) {
  std::string out = csv::line({"sound", "freq_hz", "lambda_rad2_s2", "c_per_s", "c_fit_per_s", "residual_per_s"});
  auto g17 = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double fit = damping_c_per_s(law, points[i].lambda_rad2_s2);
    out += csv::line({features[i].sound, g17(features[i].freq_hz), g17(points[i].lambda_rad2_s2),
                      g17(points[i].c_per_s), g17(fit), g17(points[i].c_per_s - fit)});
  }
  return out;
}

}  // namespace

void register_fit_damping(CLI::App& app) {
  struct Options {
    std::string features, law, estimator, plot_data, noise = "constant";
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("fit-damping", "Fit a material damping law to mode features of many strikes");
  cmd->add_option("features", opt->features, "Features CSV: sound,freq_hz,decay_per_s,amp")->required();
  cmd->add_option("--law", opt->law, "rayleigh | powerlaw | hybrid")->required();
  cmd->add_option("--estimator", opt->estimator, "emg | lsq | lb")->required();
  cmd->add_option("--noise", opt->noise,
                  "emg's normal spread: constant (Sterling et al.) | relative (grows with the decay, for "
                  "decays measured from sounds)");
  cmd->add_option("--plot-data", opt->plot_data, "Write data and fitted curve per point to this CSV");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt] {
    // Validate the options before reading anything, so a typo fails fast and names the option.
    const DampingKind law = parse_fittable_law(opt->law);
    DampingEstimator estimator{};
    try {
      estimator = parse_damping_estimator(opt->estimator);
    } catch (const std::invalid_argument& e) {
      throw InputError(SourceLocation{"--estimator", 0, 0}, e.what());
    }
    if (opt->noise != "constant" && opt->noise != "relative")
      throw InputError(SourceLocation{"--noise", 0, 0}, "unknown noise model '" + opt->noise + "' (constant, relative)");
    if (opt->noise == "relative" && estimator != DampingEstimator::emg)
      throw InputError(SourceLocation{"--noise", 0, 0}, "--noise relative applies to --estimator emg only");
    DampingFitOptions fit_options;
    fit_options.relative_noise = opt->noise == "relative";
    const auto features = read_damping_features_csv(opt->features);
    const std::size_t needed = damping_fit_param_count(law, estimator);
    if (features.size() < needed)
      throw InputError(SourceLocation{opt->features, features.back().line, 0},
                       std::to_string(features.size()) + " features, but the " + opt->law + " law fitted by " +
                           opt->estimator + " has " + std::to_string(needed) + " parameters");
    const auto points = damping_points(features);

    const auto t0 = std::chrono::steady_clock::now();
    const DampingFit fit = fit_damping(points, law, estimator, fit_options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    if (!opt->plot_data.empty()) write_file_atomically(opt->plot_data, plot_data_csv(features, points, fit.law));

    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    if (law != DampingKind::powerlaw) params["alpha"] = fit.law.alpha1;
    params["beta"] = fit.law.alpha2;
    if (law != DampingKind::rayleigh) params["alpha3"] = fit.law.alpha3;
    auto opt_json = [](const std::optional<double>& v) {
      return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
    };
    if (!fit.converged)
      std::cerr << "warning: " << opt->features << ": the optimiser stopped before converging\n";
    if (opt->json) {
      nlohmann::ordered_json j = {{"law", opt->law},
                          {"estimator", opt->estimator},
                          {"noise", estimator == DampingEstimator::emg ? nlohmann::ordered_json(opt->noise)
                                                                       : nlohmann::ordered_json(nullptr)},
                          {"params", params},
                          {"sigma", opt_json(fit.sigma_per_s)},
                          {"eta", opt_json(fit.eta_s)},
                          {"loglik", opt_json(fit.loglik)},
                          {"iterations", fit.iterations},
                          {"seconds", seconds}};
      std::cout << j.dump() << "\n";
      return;
    }
    std::cout << opt->features << ": " << points.size() << " features, law " << opt->law << " (c = 2d = "
              << (law == DampingKind::rayleigh   ? "alpha + beta lambda"
                  : law == DampingKind::powerlaw ? "beta omega^(2 alpha3)"
                                                 : "alpha + beta omega^(2 alpha3)")
              << "), estimator " << opt->estimator
              << (estimator == DampingEstimator::emg ? " (" + opt->noise + " noise)" : std::string()) << "\n";
    if (law != DampingKind::powerlaw) std::cout << "  alpha   (alpha1) = " << format_g(fit.law.alpha1) << " 1/s\n";
    std::cout << "  beta    (alpha2) = " << format_g(fit.law.alpha2) << "\n";
    if (law != DampingKind::rayleigh) std::cout << "  alpha3           = " << format_g(fit.law.alpha3) << "\n";
    if (fit.loglik) {
      std::cout << "  sigma            = " << format_g(*fit.sigma_per_s) << " 1/s\n"
                << "  eta              = " << format_g(*fit.eta_s) << " s\n"
                << "  loglik           = " << format_g(*fit.loglik) << "\n";
    }
    std::cout << "  iterations       = " << fit.iterations << "\n"
              << "  seconds          = " << format_g(seconds) << "\n";
  });
}

}  // namespace ms::cli
