// modalstudy stats limits: descending method of limits (the 2002 study's a_v procedure) per track
// (analysis/method_of_limits.hpp). Reads the export's limits.csv as written (--level level --response
// response --track participant,block,trial). Its test on series written by hand from Table 1 only
// checks how a series is read: getting Table 1 back from them is circular and says nothing about the
// paper; only a lab's own series can disagree with it.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "analysis/stats/method_of_limits.hpp"
#include "analysis/stats/quantile.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

void register_stats_limits(CLI::App& group) {
  struct Options {
    std::string data;
    LimitsColumns columns;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "limits", "Descending method of limits: the smallest level at which no change was heard, per track");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per trial, in presentation order")->required();
  cmd->add_option("--level", opt->columns.level, "Column of the level presented (falling, e.g. a_v in dB)")->required();
  cmd->add_option("--response", opt->columns.response, "Column of the answer")->required();
  cmd->add_option("--different", opt->columns.different, "Answer meaning 'heard a difference'")->capture_default_str();
  cmd->add_option("--track", opt->columns.track, "Column(s) identifying a series (e.g. participant,object)")
      ->delimiter(',');
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    nlohmann::json tracks = nlohmann::json::array();
    std::vector<double> thresholds;
    for (const LimitsSeries& s : limits_series_from_table(table, opt->columns)) {
      const LimitsThreshold t = descending_limits_threshold(s.levels, s.different);
      if (t.threshold && !t.censored) thresholds.push_back(*t.threshold);
      tracks.push_back({{"track", s.name}, {"trials", s.levels.size()}, {"threshold", opt_json(t.threshold)},
                        {"censored", t.censored},
                        {"first_different_trial", t.first_different ? nlohmann::json(*t.first_different) : nlohmann::json()}});
    }
    nlohmann::json median = nullptr;
    if (!thresholds.empty()) median = quantile(thresholds, 0.5);
    if (opt->json) {
      std::cout << nlohmann::json{{"tracks", tracks}, {"median", median}}.dump() << "\n";
      return;
    }
    std::printf("%-24s %7s %10s\n", "Track", "trials", "threshold");
    for (const auto& t : tracks) {
      const std::string th = t["threshold"].is_null() ? "above start"
                             : fmt("%g", t["threshold"].get<double>()) + (t["censored"].get<bool>() ? " (censored)" : "");
      std::printf("%-24s %7zu %10s\n", t["track"].get<std::string>().c_str(), t["trials"].get<std::size_t>(), th.c_str());
    }
    if (!median.is_null()) std::printf("median threshold (uncensored series): %g\n", median.get<double>());
  });
}

}  // namespace ms::cli
