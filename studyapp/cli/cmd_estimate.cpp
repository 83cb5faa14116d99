// modalstudy estimate REC.wav --object OBJECT.yaml [-o MATERIAL.yaml] [--json] [--report DIR]
// The material {alpha, beta, gamma, sigma} of one recorded impact on a known object
// (analysis/estimation/estimate_material.hpp): OBJECT.yaml is a parameter set whose geometry and
// strike are used, its material ignored. -o writes a material file (synthesis/material_file.hpp)
// that parameter sets use as `material: {file: MATERIAL.yaml}`. Every check (unreadable, silent or
// clipped recording, no modes above the noise, fewer than 3 recording modes matched by the estimate,
// a bad object file) runs before anything is written.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "analysis/damping/damping_features.hpp"
#include "analysis/estimation/estimate_material.hpp"
#include "analysis/estimation/residual.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/impact_recording.hpp"
#include "studyapp/cli/plot_pictures.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "studyapp/plots/plots.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/bark.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/material_file.hpp"

namespace ms::cli {

namespace {

constexpr std::size_t kMinMatchedModes = 3;

Material estimated_material(const MaterialEstimate& e, const std::string& recording, const std::string& object) {
  Material m;
  m.id = "estimated/" + std::filesystem::path(recording).stem().string();
  m.source = "modalstudy estimate " + recording + " --object " + object;
  m.rayleigh = {DampingKind::rayleigh, e.material.alpha, e.material.beta, 1.0, 0.0};
  m.specific_modulus_m2_s2 = e.material.gamma;
  m.modulus_source = "estimated with the geometry of " + object;
  m.amp_scale = e.material.sigma;
  return m;
}

// Each picture as PNG and SVG.
template <typename Draw>
void both_formats(const std::filesystem::path& dir, const std::string& stem, Draw draw) {
  draw((dir / (stem + ".png")).string());
  draw((dir / (stem + ".svg")).string());
}

// A mode where the feature metric places it: (c_z Z(f), c_d / d).
plots::XY feature_xy(const FeaturePoint& p, const FeatureMatchConstants& c) {
  return {c.c_z * bark_wang_sekey_gersho(p.freq_hz), c.c_d / p.decay_per_s};
}

void write_report(const std::string& dir, const ImpactRecording& rec, const PerceptualReference& ref,
                  const std::vector<float>& synthesis, const ModalModel& model, const MaterialEstimate& e,
                  const nlohmann::json& json) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  const fs::path d(dir);
  const BarkImage syn = ref.sone_image(synthesis);
  const std::size_t frames = std::max(ref.sone().frames, syn.frames);
  plots::PlotOptions o;
  o.title = "Loudness of the recording " + fs::path(rec.path).filename().string() + " [sone]";
  both_formats(d, "spectrogram_recording", [&](const std::string& p) {
    plots::loudness_image(p, by_band(ref.sone(), frames), ref.sone().hop_s, ref.sone().band_bark, false, o);
  });
  o.title = "Loudness of the estimated material's synthesis [sone]";
  both_formats(d, "spectrogram_synthesis", [&](const std::string& p) {
    plots::loudness_image(p, by_band(syn, frames), ref.sone().hop_s, ref.sone().band_bark, false, o);
  });
  // The recording's modes as (lambda, c = 2d) with the estimated Rayleigh line c = alpha + beta lambda.
  std::vector<double> lambda, c;
  for (const Mode& m : rec.modes) {
    const DampingPoint p = damping_point(m.freq_hz, m.decay_per_s);
    lambda.push_back(p.lambda_rad2_s2);
    c.push_back(p.c_per_s);
  }
  const auto [lo, hi] = std::minmax_element(lambda.begin(), lambda.end());
  char name[160];
  std::snprintf(name, sizeof name, "estimate: c = %.4g + %.4g lambda", e.material.alpha, e.material.beta);
  const DampingLaw law{DampingKind::rayleigh, e.material.alpha, e.material.beta, 1.0, 0.0};
  o.title = "Recording's modes (lambda, c = 2d) and the estimated Rayleigh law";
  both_formats(d, "damping", [&](const std::string& p) {
    plots::damping_scatter(p, lambda, c, {{name, sample_law(law, *lo, *hi)}}, o, true);
  });
  // Every audible recording mode joined to the synthesis mode it matches best.
  const FeatureMatchConstants& fc = EstimateOptions{}.perceptual.match;
  const auto others = loudness_weighted_features(model.modes, ref.imager(), ref.db_spl_at_unit_power(), ref.sone().frames);
  std::vector<plots::XY> points;
  std::vector<std::string> labels;
  plots::MapOverlay matches;
  matches.name = "synthesis mode matched (k > 0)";
  matches.base_name = "recording mode";
  matches.procrustes_align = false;
  for (const FeaturePoint& p : ref.features()) {
    if (!(p.weight > 0)) continue;
    double best = 0.0;
    plots::XY at{NAN, NAN};
    for (const FeaturePoint& q : others)
      if (const double k = point_match_score(feature_distance(p, q, fc)); k > best) best = k, at = feature_xy(q, fc);
    points.push_back(feature_xy(p, fc));
    labels.push_back(format_g(p.freq_hz, 4) + " Hz");
    matches.points.push_back(at);
  }
  o.title = "Feature matches: recording modes and the synthesis modes they match";
  o.x_label = "5 Z(f) [5 x Bark]";
  o.y_label = "100 / d [100 x s]";
  both_formats(d, "feature_matches", [&](const std::string& p) { plots::mds_map(p, points, labels, o, matches); });
  write_file_atomically((d / "estimate.json").string(), json.dump(2) + "\n");
}

}  // namespace

void register_estimate(CLI::App& app) {
  struct Options {
    std::string recording, object, output, report;
    int channel = -1;
    double playback_db = 70.0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("estimate", "Material {alpha, beta, gamma, sigma} from one recorded impact");
  cmd->add_option("recording", opt->recording, "Recorded impact (WAV/FLAC/AIFF)")->required();
  cmd->add_option("--object", opt->object, "Parameter set of the struck object (its material is ignored)")->required();
  cmd->add_option("-o,--output", opt->output, "Write the estimated material file here (YAML)");
  cmd->add_option("--report", opt->report,
                  "Write pictures (spectrograms, damping, feature matches; PNG and SVG) and estimate.json here");
  cmd->add_option("--channel", opt->channel, "0-based channel to analyse (default: mix to mono)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--playback-db", opt->playback_db, "SPL [dB] of the recording's loudest loudness cell (default 70)")
      ->check(CLI::Range(0.0, 130.0));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt] {
    namespace fs = std::filesystem;
    remove_temporaries_on_signals();
    if (std::error_code ec; !opt->report.empty() && fs::exists(opt->report, ec) && !fs::is_directory(opt->report, ec))
      throw InputError(SourceLocation{opt->report, 0, 0}, "--report must be a folder");
    const ObjectEigen object = object_eigen_from_paramset(opt->object);
    ImpactRecording rec = load_impact_recording(opt->recording, opt->channel);
    extract_impact_modes(rec);
    EstimateOptions options;
    options.perceptual.playback_db_spl = opt->playback_db;
    options.noise_sigma = rec.noise_sigma;
    const auto start = std::chrono::steady_clock::now();
    MaterialEstimate e;
    try {
      e = estimate_material(rec.samples, rec.sample_rate_hz, rec.modes, object, object.strike, options);
    } catch (const std::invalid_argument& err) {
      throw InputError(SourceLocation{opt->recording, 0, 0}, err.what());
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (e.matched_modes < kMinMatchedModes)
      throw InputError(SourceLocation{opt->recording, 0, 0},
                       "only " + std::to_string(e.matched_modes) + " of its " + std::to_string(rec.modes.size()) +
                           " modes matched by the modes of " + opt->object + " (at least " +
                           std::to_string(kMinMatchedModes) + " needed): not this object?");
    const Material material = estimated_material(e, opt->recording, opt->object);
    const nlohmann::json j = {
        {"material", {{"alpha", e.material.alpha}, {"beta", e.material.beta}, {"gamma", e.material.gamma},
                      {"sigma", e.material.sigma}}},
        {"metric", {{"image", e.scores.psycho}, {"feature", e.scores.match.product}, {"hybrid", num_json(e.scores.hybrid)}}},
        {"contact_s", e.contact_s},
        {"starts", e.starts.size()},
        {"iterations", e.iterations},
        {"seconds", seconds},
        {"matched_modes", e.matched_modes}};
    std::string residual;  // MATERIAL.residual.msr beside the material file (analysis/estimation/residual.hpp)
    if (!opt->output.empty()) {
      residual = write_residual(opt->output, rec.samples, rec.sample_rate_hz, object, object.strike, e.material,
                                material.source);
      write_file_atomically(opt->output, material_file_yaml(material));
    }
    if (!opt->report.empty()) {
      const ModalModel model = candidate_model(object, e.material, 0.5 * rec.sample_rate_hz);
      const std::vector<float> synthesis =
          render_candidate(model, object.strike, rec.sample_rate_hz, e.frames);
      const std::vector<float> head(rec.samples.begin(), rec.samples.begin() + std::ptrdiff_t(e.frames));
      const PerceptualReference ref(head, rec.sample_rate_hz, rec.modes, options.perceptual);
      write_report(opt->report, rec, ref, synthesis, model, e, j);
    }
    if (opt->json) {
      std::cout << j.dump() << "\n";
      return;
    }
    std::printf("%s on %s: %zu modes from the onset at %.4f s\n", opt->recording.c_str(), opt->object.c_str(),
                rec.modes.size(), rec.onset_s);
    for (std::size_t i = 0; i < e.starts.size(); ++i) {
      const StartResult& s = e.starts[i];
      std::printf("start %zu: alpha %.5g beta %.5g gamma %.5g sigma %.5g -> Pi_hybrid %.6g (%zu iterations)\n", i + 1,
                  s.fitted.alpha, s.fitted.beta, s.fitted.gamma, s.fitted.sigma, s.scores.hybrid, s.iterations);
    }
    std::printf("material: alpha %.6g 1/s, beta %.6g s, gamma %.6g m^2/s^2, sigma %.6g (strike contact %.3g ms)\n",
                e.material.alpha, e.material.beta, e.material.gamma, e.material.sigma, 1e3 * e.contact_s);
    std::printf("metric: Pi_psycho %.6g sone^2, Pi_MRP %.4f, Pi_hybrid %.6g; %zu modes matched; %.2f s\n",
                e.scores.psycho, e.scores.match.product, e.scores.hybrid, e.matched_modes, seconds);
    if (!opt->output.empty()) std::printf("material file: %s\nresidual file: %s\n", opt->output.c_str(), residual.c_str());
    if (!opt->report.empty()) std::printf("report: %s\n", opt->report.c_str());
  });
}

}  // namespace ms::cli
