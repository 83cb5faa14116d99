// modalstudy audit --measured WAV... [--model PARAMSET.yaml] [--report DIR] [--json]
// Compares a model with recordings of one object, names the effects the model is missing and shows
// the gap shrink (analysis/audit/audit.hpp; README "Auditing a model").
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "analysis/audit/audit.hpp"
#include "analysis/audit/augmented_paramset.hpp"
#include "analysis/audit/gap_location.hpp"
#include "analysis/audit/given_model.hpp"
#include "analysis/damping/damping_features.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/plots/plots.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"

namespace ms::cli {

namespace {

using audit::AuditResult;

nlohmann::json result_json(const AuditResult& r, const audit::AuditData& data) {
  nlohmann::json named = nlohmann::json::array();
  for (const auto& n : r.named) {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [k, v] : n.parameters) params[k] = v;
    named.push_back({{"effect", n.effect},
                     {"gap_before", n.gap_before_db},
                     {"gap_after", n.gap_after_db},
                     {"cv_improvement", n.cv_improvement_db},
                     {"share_above_floor", n.share_above_floor},
                     {"named_on_own_test", n.named_on_own_test},
                     {"parameters", params},
                     {"evidence", n.evidence}});
  }
  // Every round's candidates: the audit's whole decision trail (the first round is also given alone).
  nlohmann::json rounds = nlohmann::json::array();
  for (const auto& round : r.rounds) {
    nlohmann::json candidates = nlohmann::json::array();
    for (const auto& c : round)
      candidates.push_back({{"effect", c.effect}, {"tested", c.tested}, {"statistic", c.statistic},
                            {"detector_passes", c.detector_passes}, {"cv_gap", c.cv_gap_db},
                            {"improvement", c.improvement_db}, {"note", c.note}});
    rounds.push_back(candidates);
  }
  const nlohmann::json candidates = rounds.empty() ? nlohmann::json::array() : rounds.front();
  const audit::SpectrogramGrid& g = data.measured.grids[audit::kDecay];
  nlohmann::json strikes = nlohmann::json::array();
  for (std::size_t s = 0; s < r.strikes; ++s)
    strikes.push_back({{"strike", data.measured.strikes[s].name}, {"gap_before", r.location.strike_gap_db[s]},
                       {"gap_after", r.after[s].gap_db}, {"gain_db", r.strike_gain_db[s]},
                       {"gap_before_held_out", s < r.strike_cv_gap_before_db.size() ? nlohmann::json(r.strike_cv_gap_before_db[s]) : nlohmann::json()},
                       {"gap_after_held_out", s < r.strike_cv_gap_after_db.size() ? nlohmann::json(r.strike_cv_gap_after_db[s]) : nlohmann::json()},
                       {"floor", r.strike_floor_db[s]}});
  // The three worst Bark bands and the worst frame of the baseline.
  nlohmann::json worst_bands = nlohmann::json::array();
  for (std::size_t b : audit::worst_bands(r.location, 3))
    worst_bands.push_back({{"bark", b}, {"centre_hz", std::round(g.band_centre_hz(b))}, {"gap", r.location.band_gap_db[b]}});
  nlohmann::json worst_modes = nlohmann::json::array();
  for (std::size_t n : r.location.worst_modes) worst_modes.push_back(std::round(r.baseline.modes[n].freq_hz * 10) / 10);
  // Per-mode residuals of the baseline, per strike (measured - model).
  nlohmann::json residuals = nlohmann::json::array();
  for (const auto& m : r.residuals_before)
    residuals.push_back({{"strike", data.measured.strikes[m.strike].name}, {"freq_hz", m.freq_hz},
                         {"freq_rel", m.freq_rel}, {"decay_rel", m.decay_rel}, {"amp_db", m.amp_db}});
  nlohmann::json untested = r.untested;
  return {{"metric", r.metric},
          {"gap_before", r.gap_before_db},
          {"gap_after", r.gap_after_db},
          {"cv_gap_before", r.cv_gap_before_db},
          {"cv_gap_after", r.cv_gap_after_db},
          {"floor_db", r.floor_db},
          {"share_above_floor", r.share_above_floor},
          {"left_shared", {{"mean_db", r.left_shared.mean_db},
                           {"standard_error_db", r.left_shared.standard_error_db},
                           {"resolved", r.left_shared.resolved()}}},
          {"strikes", r.strikes},
          {"modes", r.modes},
          {"named_effects", named},
          {"first_round", candidates},
          {"rounds", rounds},
          {"locate", {{"strikes", strikes},
                      {"worst_bands", worst_bands},
                      {"worst_time_s", g.frame_time_s(audit::worst_frame(r.location))},
                      {"worst_modes_hz", worst_modes},
                      {"decay_spread", r.decay_spread},
                      {"strike_variation_db", data.strike_variation_db},
                      {"mode_residuals", residuals}}},
          {"untested", untested}};
}

std::vector<plots::XY> law_curve(const DampingLaw& law, double lo, double hi) {
  std::vector<plots::XY> pts;
  for (int k = 0; k <= 60; ++k) {
    const double lambda = lo * std::pow(hi / lo, k / 60.0);
    pts.push_back({lambda, 2.0 * law.decay_per_s(lambda)});
  }
  return pts;
}

void write_report(const std::string& dir, const AuditResult& r, const audit::AuditData& data,
                  const nlohmann::json& json) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path d(dir);
  const double duration = double(data.measured.strikes.front().samples.size()) / data.measured.sample_rate_hz;
  plots::PlotOptions o;
  o.width_px = 900;
  o.height_px = 500;
  char title[200];
  std::snprintf(title, sizeof title, "Residual, baseline (model - measured, mean over strikes): gap %.2f dB", r.gap_before_db);
  o.title = title;
  plots::residual_map((d / "residual_before.png").string(), audit::mean_gap_map(r.before), duration, 20.0, o);
  std::snprintf(title, sizeof title, "Residual, with the named effects: gap %.2f dB", r.gap_after_db);
  o.title = title;
  plots::residual_map((d / "residual_after.png").string(), audit::mean_gap_map(r.after), duration, 20.0, o);
  // Per-strike gap before and after, with the repeatability floor as a line.
  auto per_strike = [](const std::string& name, auto value, std::size_t strikes) {
    plots::Series s{name, {}};
    for (std::size_t k = 0; k < strikes; ++k) s.points.push_back({double(k + 1), value(k)});
    return s;
  };
  std::snprintf(title, sizeof title, "Gap per strike; repeatability floor %.2f dB (held-out)", r.floor_db);
  o.title = title;
  o.x_label = "strike";
  o.y_label = "gap [dB]";
  plots::line_plot((d / "gap_per_strike.png").string(),
                   {per_strike("baseline (in-sample)", [&](std::size_t k) { return r.before[k].gap_db; }, r.strikes),
                    per_strike("with effects (in-sample)", [&](std::size_t k) { return r.after[k].gap_db; }, r.strikes),
                    per_strike("repeatability floor (held out)", [&](std::size_t k) { return r.strike_floor_db[k]; }, r.strikes),
                    // Drawn last: where it reaches the floor it covers it.
                    per_strike("with effects (held out)", [&](std::size_t k) { return r.strike_cv_gap_after_db[k]; },
                               r.strike_cv_gap_after_db.size())},
                   o);
  // Per-mode residuals: amplitude (dB) and decay (%) against frequency, before and after.
  auto series = [](const std::vector<audit::ModeResidual>& res, bool amp, const std::string& name) {
    plots::Series s{name, {}};
    for (const auto& x : res) s.points.push_back({x.freq_hz, amp ? x.amp_db : 100.0 * x.decay_rel});
    std::sort(s.points.begin(), s.points.end(), [](auto& a, auto& b) { return a.x < b.x; });
    return s;
  };
  o.title = "Per-mode amplitude residual (measured - model), every strike";
  o.x_label = "frequency [Hz]";
  o.y_label = "amplitude residual [dB]";
  plots::line_plot((d / "mode_amplitude_residuals.png").string(),
                   {series(r.residuals_before, true, "baseline"), series(r.residuals_after, true, "with effects")}, o, true);
  o.title = "Per-mode decay residual (measured - model), every strike";
  o.y_label = "decay residual [%]";
  plots::line_plot((d / "mode_decay_residuals.png").string(),
                   {series(r.residuals_before, false, "baseline"), series(r.residuals_after, false, "with effects")}, o, true);
  // (lambda, c) scatter with the baseline's and the final model's laws.
  std::vector<double> lambda, c;
  for (const auto& t : data.tracks)
    for (const auto& ob : t.strikes)
      if (ob.present) {
        const DampingPoint p = damping_point(ob.freq_hz, ob.decay_per_s);
        lambda.push_back(p.lambda_rad2_s2);
        c.push_back(p.c_per_s);
      }
  const double lo = *std::min_element(lambda.begin(), lambda.end()), hi = *std::max_element(lambda.begin(), lambda.end());
  std::vector<plots::Series> laws;
  if (r.baseline.law_fitted) laws.push_back({"baseline (Rayleigh)", law_curve(r.baseline.law, lo, hi)});
  if (r.final_model.law_fitted && !r.named.empty()) laws.push_back({"with effects", law_curve(r.final_model.law, lo, hi)});
  o = plots::PlotOptions{};
  o.title = "Damping: measured (lambda, c = 2d) and the laws";
  plots::damping_scatter((d / "damping.png").string(), lambda, c, laws, o, true);
  std::string effects;
  for (const auto& n : r.named) effects += (effects.empty() ? "" : ", ") + n.effect;
  const std::string yaml = audit::augmented_paramset_yaml(
      data, r.final_model,
      "modalstudy audit: the plain model fitted to " + std::to_string(r.strikes) + " strikes" +
          (effects.empty() ? "" : " + " + effects) + "; renders strike " +
          data.measured.strikes[audit::representative_strike(r.final_model)].name);
  write_file_atomically((d / "model.yaml").string(), yaml);
  write_file_atomically((d / "audit.json").string(), json.dump(2) + "\n");
}

}  // namespace

void register_audit(CLI::App& app) {
  struct Options {
    std::vector<std::string> measured;
    std::string model, report;
    bool json = false;
    double max_duration_s = 2.0;
    double skip_contact_ms = 0.5;
    double attack_skip_ms = 20.0;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("audit", "Find where a model and recordings disagree and name the missing effect");
  cmd->add_option("--measured", opt->measured, "Recordings of one object, one strike each (WAV/FLAC/AIFF)")
      ->required()->expected(1, -1);
  cmd->add_option("--model", opt->model, "Parameter set to audit (default: the plain model fitted to the recordings)");
  cmd->add_option("--report", opt->report, "Write pictures, audit.json and model.yaml (the improved model) here");
  cmd->add_option("--max-duration-s", opt->max_duration_s, "Analysed span after each onset (default 2)")
      ->check(CLI::Range(0.3, 30.0));
  cmd->add_option("--skip-contact-ms", opt->skip_contact_ms, "As for extract (default 0.5)")->check(CLI::Range(0.0, 20.0));
  cmd->add_option("--max-attack-skip-ms", opt->attack_skip_ms, "As for extract (default 20; 0: off)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt] {
    std::optional<ParamSet> given;
    if (!opt->model.empty()) given = load_paramset(opt->model);
    if (std::error_code ec; !opt->report.empty() && std::filesystem::exists(opt->report, ec) &&
        !std::filesystem::is_directory(opt->report, ec))
      throw InputError(SourceLocation{opt->report, 0, 0}, "--report must be a folder");
    std::vector<audit::Recording> recordings;
    for (const std::string& path : opt->measured) {
      const Audio a = read_audio(path);
      recordings.push_back({path, a.sample_rate_hz, mono(a)});
    }
    audit::AuditOptions options;
    options.strikes.max_duration_s = opt->max_duration_s;
    options.strikes.skip_contact_s = opt->skip_contact_ms * 1e-3;
    options.strikes.max_attack_skip_s = opt->attack_skip_ms * 1e-3;
    try {
      const audit::AuditData data = audit::make_audit_data(recordings, options);
      std::optional<ModalModel> model;
      if (given) {
        model = audit::given_model(*given, opt->model, data.measured.sample_rate_hz);
        options.object_shapes = audit::object_shapes(opt->model, *model, data.measured.sample_rate_hz);
      }
      const AuditResult r = audit::run_audit(data, model, options);
      const nlohmann::json j = result_json(r, data);
      if (!opt->report.empty()) write_report(opt->report, r, data, j);
      if (opt->json) {
        std::cout << j.dump() << "\n";
        return;
      }
      std::printf("%zu strikes, %zu modes; gap (%s)\n", r.strikes, r.modes, r.metric.c_str());
      std::printf("baseline: %.2f dB (held-out %.2f dB)\n", r.gap_before_db, r.cv_gap_before_db);
      std::printf("repeatability floor: %.2f dB (held-out strikes against the best model of the others; "
                  "%.2f dB of the held-out gap lies above it)\n",
                  r.floor_db, std::max(0.0, r.cv_gap_before_db - r.floor_db));
      if (r.named.empty() && r.left_shared.resolved())
        std::printf("nothing named, yet the strikes share something the model lacks: the other strikes' mean "
                    "residual predicts a held-out strike %.2f +- %.2f dB better than the model, and no effect in the "
                    "catalog lowers the held-out gap enough (an effect the catalog does not hold, or one too weak for "
                    "its detector)\n",
                    r.left_shared.mean_db, r.left_shared.standard_error_db);
      else if (r.named.empty())
        std::printf("nothing named, and nothing the strikes share is missing: the other strikes' mean residual "
                    "predicts a held-out strike %.2f +- %.2f dB better than the model, under what the audit resolves "
                    "(%.2f dB and two standard errors); what is left is how the strikes differ (repetition, or an "
                    "effect that varies from strike to strike, such as hand damping, a contact or a moving hit "
                    "point, too weak for its detector)\n",
                    r.left_shared.mean_db, r.left_shared.standard_error_db, audit::kSharedResolutionDb);
      for (const auto& n : r.named) {
        if (n.named_on_own_test)
          std::printf("+ %-17s gap %.2f -> %.2f dB, named on its own test (the held-out gap cannot judge it here; "
                      "held-out change %+.2f dB): %s\n", n.effect.c_str(), n.gap_before_db, n.gap_after_db,
                      std::round(100.0 * n.cv_improvement_db) / 100.0 + 0.0, n.evidence.c_str());  // no "-0.00"
        else
          std::printf("+ %-17s gap %.2f -> %.2f dB, closes %.0f %% of the gap above the floor: %s\n", n.effect.c_str(),
                      n.gap_before_db, n.gap_after_db, 100.0 * n.share_above_floor, n.evidence.c_str());
        for (const auto& [k, v] : n.parameters) std::printf("    %s = %.4g\n", k.c_str(), v);
      }
      std::printf("final: %.2f dB (held-out %.2f dB; %.0f %% of the gap above the floor closed)\n", r.gap_after_db,
                  r.cv_gap_after_db, 100.0 * r.share_above_floor);
      if (!r.named.empty())
        std::printf("left: what the other strikes share beyond the final model predicts a held-out strike %.2f +- %.2f "
                    "dB better (%s)\n",
                    r.left_shared.mean_db, r.left_shared.standard_error_db,
                    r.left_shared.resolved() ? "resolved: the strikes share something the named effects do not explain"
                                             : "under what the audit resolves: nothing the strikes share is left");
      for (const auto& u : r.untested) std::printf("not tested: %s\n", u.c_str());
      if (!opt->report.empty()) std::printf("report: %s\n", opt->report.c_str());
    } catch (const audit::AuditError& e) {
      throw InputError(std::string("audit: ") + e.what());
    }
  });
}

}  // namespace ms::cli
