// modalstudy stats staircase: adaptive-staircase thresholds per track (analysis/staircase.hpp).
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "analysis/stats/mushra.hpp"
#include "analysis/stats/staircase.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

void register_stats_staircase(CLI::App& group) {
  struct Options {
    std::string data;
    StaircaseColumns columns{"", "", "next_level", {}};
    std::size_t reversals = 0;
    bool log_scale = false, json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "staircase", "Adaptive-staircase thresholds per track: mean reversal level after the first two (as the protocol's)");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per trial")->required();
  cmd->add_option("--level", opt->columns.level, "Column of the stimulus level presented")->required();
  cmd->add_option("--track", opt->columns.track, "Column(s) identifying a track (e.g. participant, staircase)");
  cmd->add_option("--trial", opt->columns.trial, "Column ordering the trials (default: file order)");
  cmd->add_option("--next-level", opt->columns.next_level,
                  "Column of the level after each answer, so a reversal at a track's last trial counts (used when "
                  "present)")
      ->capture_default_str();
  cmd->add_option("--reversals", opt->reversals,
                  "Average the last K reversals (default: all but the first two, all when there are at most four)")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("--log", opt->log_scale, "Geometric mean (levels on a ratio scale)");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    const StaircaseTracks read = staircase_tracks_from_table(table, opt->columns, opt->log_scale);
    StaircaseOptions so;
    if (opt->reversals > 0) so.last_k = opt->reversals;
    so.log_scale = opt->log_scale;
    nlohmann::json tracks = nlohmann::json::array();
    std::vector<std::string> notices;
    if (!read.has_next_level)
      notices.push_back("no column '" + opt->columns.next_level +
                        "' (the level after each answer): a reversal at a track's last trial is not counted");
    std::vector<double> thresholds;
    for (const StaircaseTrackLevels& track : read.tracks) {
      const StaircaseThreshold t = staircase_threshold(track.levels, track.next_level, so);
      if (so.last_k && t.used < *so.last_k)
        notices.push_back("track '" + (track.name.empty() ? std::string("all") : track.name) + "' has " +
                          std::to_string(t.reversal_levels.size()) + " reversals, fewer than " +
                          std::to_string(*so.last_k));
      if (t.threshold) thresholds.push_back(*t.threshold);
      tracks.push_back({{"track", track.name}, {"trials", track.levels.size()}, {"reversal_levels", t.reversal_levels},
                        {"used", t.used}, {"threshold", opt_json(t.threshold)}, {"sd", opt_json(t.sd)}});
    }
    nlohmann::json overall = nullptr;
    if (thresholds.size() >= 2) {
      const MushraStat s = describe("threshold", thresholds, 0.95);
      overall = {{"n", s.n}, {"mean", s.mean}, {"sd", s.sd}, {"ci_low", opt_json(s.ci_low)}, {"ci_high", opt_json(s.ci_high)}};
    }
    print_notices(notices, opt->data);
    if (opt->json) {
      std::cout << nlohmann::json{{"reversals", so.last_k ? nlohmann::json(*so.last_k) : nlohmann::json("all but the first two")},
                                  {"log", opt->log_scale}, {"tracks", tracks}, {"overall", overall},
                                  {"notices", notices}}.dump()
                << "\n";
      return;
    }
    std::printf("%-20s %7s %10s %6s %12s\n", "Track", "trials", "reversals", "used", "threshold");
    for (const auto& t : tracks)
      std::printf("%-20s %7zu %10zu %6zu %12s\n", t["track"].get<std::string>().c_str(), t["trials"].get<std::size_t>(),
                  t["reversal_levels"].size(), t["used"].get<std::size_t>(),
                  t["threshold"].is_null() ? "NA" : fmt("%.4g", t["threshold"].get<double>()).c_str());
    if (!overall.is_null())
      std::printf("mean over tracks %.4g, 95%% CI [%.4g, %.4g]\n", overall["mean"].get<double>(),
                  overall["ci_low"].get<double>(), overall["ci_high"].get<double>());
  });
}

}  // namespace ms::cli
