// modalstudy compare A.wav B.wav [--metric image|feature|hybrid] [--json] [--plot DIR] [--playback-db L]
// Ren et al.'s perceptual metric between two recordings (analysis/estimation/perceptual_metric.hpp):
// Pi_psycho of their loudness images, the match ratios and Match Ratio Product of their extracted
// modes, and Pi_hybrid. A is the reference: its loudest image cell is played at --playback-db and B with
// the same gain. Both are read from their onsets. Different sample rates are refused (no resampling),
// as are silent, clipped or unreadable files; every check runs before anything is written.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "analysis/estimation/perceptual_metric.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/impact_recording.hpp"
#include "studyapp/cli/plot_pictures.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "studyapp/plots/plots.hpp"
#include "synthesis/input_error.hpp"

namespace ms::cli {

void register_compare(CLI::App& app) {
  struct Options {
    std::string a, b, metric, plot_dir;
    double playback_db = 70.0;
    int channel = -1;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("compare", "Perceptual distance between two impact recordings (Ren et al.)");
  cmd->add_option("a", opt->a, "Reference recording (WAV/FLAC/AIFF)")->required();
  cmd->add_option("b", opt->b, "Recording compared with it (same sample rate)")->required();
  cmd->add_option("--metric", opt->metric,
                  "Only this metric: image (Pi_psycho), feature (match ratios, Pi_MRP) or hybrid "
                  "(Pi_psycho / |Pi_MRP|); default: all three")
      ->check(CLI::IsMember({"image", "feature", "hybrid"}));
  cmd->add_option("--playback-db", opt->playback_db,
                  "SPL [dB] at which A's loudest loudness-image cell is played (B with the same gain; default 70)")
      ->check(CLI::Range(0.0, 130.0));
  cmd->add_option("--channel", opt->channel, "0-based channel to analyse (default: mix to mono)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--plot", opt->plot_dir,
                  "Write loudness_a.png, loudness_b.png and loudness_difference.png (B - A) into this folder");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt] {
    namespace fs = std::filesystem;
    if (std::error_code ec; !opt->plot_dir.empty() && fs::exists(opt->plot_dir, ec) && !fs::is_directory(opt->plot_dir, ec))
      throw InputError(SourceLocation{opt->plot_dir, 0, 0}, "--plot must be a folder");
    const bool image = opt->metric.empty() || opt->metric == "image" || opt->metric == "hybrid";
    const bool feature = opt->metric.empty() || opt->metric == "feature" || opt->metric == "hybrid";
    ImpactRecording a = load_impact_recording(opt->a, opt->channel), b = load_impact_recording(opt->b, opt->channel);
    if (b.sample_rate_hz != a.sample_rate_hz) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "sample rate %g Hz differs from %g Hz of %s (compare does not resample)",
                    b.sample_rate_hz, a.sample_rate_hz, opt->a.c_str());
      throw InputError(SourceLocation{opt->b, 0, 0}, buf);
    }
    if (feature) {
      extract_impact_modes(a);
      extract_impact_modes(b);
    }
    PerceptualOptions options;
    options.playback_db_spl = opt->playback_db;
    const PerceptualReference ref(a.samples, a.sample_rate_hz, a.modes, options);
    const BarkImage b_sone = ref.sone_image(b.samples);
    PerceptualScores s;
    s.psycho = psycho_distance(ref.sone(), b_sone);
    const auto b_points =
        loudness_weighted_features(b.modes, ref.imager(), ref.db_spl_at_unit_power(), ref.sone().frames);
    s.match = match_ratio_product(ref.features(), b_points, options.match);
    s.hybrid = hybrid_metric(s.psycho, s.match);

    if (!opt->plot_dir.empty()) {
      fs::create_directories(opt->plot_dir);
      const std::size_t frames = std::max(ref.sone().frames, b_sone.frames);
      const auto ia = by_band(ref.sone(), frames), ib = by_band(b_sone, frames);
      auto diff = ib;
      for (std::size_t band = 0; band < diff.size(); ++band)
        for (std::size_t m = 0; m < frames; ++m) diff[band][m] -= ia[band][m];
      const double hop = ref.sone().hop_s, bark = ref.sone().band_bark;
      plots::PlotOptions o;
      o.title = "Loudness of " + fs::path(opt->a).filename().string() + " [sone]";
      plots::loudness_image((fs::path(opt->plot_dir) / "loudness_a.png").string(), ia, hop, bark, false, o);
      o.title = "Loudness of " + fs::path(opt->b).filename().string() + " [sone]";
      plots::loudness_image((fs::path(opt->plot_dir) / "loudness_b.png").string(), ib, hop, bark, false, o);
      o.title = "Loudness difference B - A [sone]";
      plots::loudness_image((fs::path(opt->plot_dir) / "loudness_difference.png").string(), diff, hop, bark, true, o);
    }

    if (opt->json) {
      nlohmann::json j = {{"a", opt->a},
                          {"b", opt->b},
                          {"sample_rate", a.sample_rate_hz},
                          {"playback_db_spl", opt->playback_db},
                          {"onset_s", {{"a", a.onset_s}, {"b", b.onset_s}}}};
      if (image)
        j["image"] = {{"psycho", s.psycho},
                      {"frames", {{"a", ref.sone().frames}, {"b", b_sone.frames}}},
                      {"bands", ref.sone().bands},
                      {"band_bark", ref.sone().band_bark},
                      {"hop_s", ref.sone().hop_s}};
      if (feature)
        j["feature"] = {{"match_ratio_a", s.match.reference},
                        {"match_ratio_b", s.match.estimate},
                        {"mrp", s.match.product},
                        {"modes", {{"a", a.modes.size()}, {"b", b.modes.size()}}}};
      if (image && feature) j["hybrid"] = num_json(s.hybrid);
      if (!opt->plot_dir.empty()) j["plot_dir"] = opt->plot_dir;
      std::cout << j.dump() << "\n";
    } else {
      std::printf("%s vs %s at %g Hz, from their onsets (%.4f s, %.4f s); %s's loudest cell at %g dB SPL\n",
                  opt->a.c_str(), opt->b.c_str(), a.sample_rate_hz, a.onset_s, b.onset_s, opt->a.c_str(),
                  opt->playback_db);
      if (image)
        std::printf("image    Pi_psycho = %.6g sone^2 (%zu x %zu frames x %zu Bark bands)\n", s.psycho,
                    ref.sone().frames, b_sone.frames, ref.sone().bands);
      if (feature)
        std::printf("feature  R = %.4f, R~ = %.4f, Pi_MRP = %.4f (%zu and %zu modes)\n", s.match.reference,
                    s.match.estimate, s.match.product, a.modes.size(), b.modes.size());
      if (image && feature) std::printf("hybrid   Pi_hybrid = %.6g\n", s.hybrid);
      if (!opt->plot_dir.empty()) std::printf("plots: %s\n", opt->plot_dir.c_str());
    }
  });
}

}  // namespace ms::cli
