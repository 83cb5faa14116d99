// modalstudy stats changepoint: Fig. 5.4 of Skandalou & Ireland 2017 from the export's changepoint.csv
// (one row per sound of a sweep): per value of the swept parameter, how many sweeps marked a material
// change there, per group (--by object) and over all groups, and the values marked most often
// (analysis/stats/change_points.hpp).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "analysis/stats/change_points.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

namespace {

nlohmann::json group_json(const ChangepointGroup& g) {
  nlohmann::json counts = nlohmann::json::array();
  for (std::size_t i = 0; i < g.values.size(); ++i) counts.push_back({{"value", g.values[i]}, {"marks", g.marks[i]}});
  return {{"group", g.name}, {"sweeps", g.sweeps}, {"counts", counts}, {"most_chosen", g.most_chosen}};
}

// Values down, groups across (the last one all sweeps together when there are several groups); a group
// that never played a value shows "-".
void print_counts(const std::vector<ChangepointGroup>& groups, const std::string& value_name) {
  std::vector<double> values;
  for (const auto& g : groups) values.insert(values.end(), g.values.begin(), g.values.end());
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::size_t width = 6;
  for (const auto& g : groups) width = std::max(width, g.name.size());
  std::printf("Sweeps marking a change at each value (Skandalou & Ireland 2017, Fig. 5.4)\n%-10s", value_name.c_str());
  for (const auto& g : groups) std::printf(" %*s", int(width), g.name.c_str());
  std::printf("\n");
  for (double v : values) {
    std::printf("%-10s", format_g(v, 6).c_str());
    for (const auto& g : groups) {
      const auto it = std::find(g.values.begin(), g.values.end(), v);
      std::printf(" %*s", int(width), it == g.values.end() ? "-" : std::to_string(g.marks[std::size_t(it - g.values.begin())]).c_str());
    }
    std::printf("\n");
  }
  std::printf("%-10s", "sweeps");
  for (const auto& g : groups) std::printf(" %*zu", int(width), g.sweeps);
  std::printf("\nmost chosen (marks of sweeps):\n");
  for (const auto& g : groups) {
    std::string list;
    for (double v : g.most_chosen) {
      const std::size_t i = std::size_t(std::find(g.values.begin(), g.values.end(), v) - g.values.begin());
      list += (list.empty() ? "" : ", ") + format_g(v, 6) + " (" + std::to_string(g.marks[i]) + "/" +
              std::to_string(g.sweeps) + ")";
    }
    std::printf("  %-*s %s\n", int(width), g.name.c_str(), list.empty() ? "no marks" : list.c_str());
  }
}

}  // namespace

void register_stats_changepoint(CLI::App& group) {
  struct Options {
    std::string data;
    ChangepointColumns columns;
    std::size_t top = 4;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "changepoint", "Change-point judgements over sweeps (Skandalou & Ireland 2017, Exp. 3): marks per value of the "
                     "swept parameter and the values marked most often (Fig. 5.4)");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per sound of a sweep (the export's changepoint.csv)")->required();
  cmd->add_option("--value", opt->columns.value, "Column of the swept parameter's value")->capture_default_str();
  cmd->add_option("--marked", opt->columns.marked, "Column saying whether the sound was marked (1/0)")->capture_default_str();
  cmd->add_option("--sweep", opt->columns.sweep, "Columns identifying one sweep heard")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--by", opt->columns.by, "Group column(s), e.g. object or object,method (the stimuli's factors)")
      ->delimiter(',');
  cmd->add_option("--top", opt->top, "How many most-chosen values per group (ties at the cut kept)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    std::vector<ChangepointGroup> groups = change_points_from_table(table, opt->columns, opt->top);
    if (opt->columns.by.empty()) groups.front().name = "all";
    if (groups.size() > 1) {  // and all of them together
      ChangepointColumns all = opt->columns;
      all.by.clear();
      ChangepointGroup pooled = change_points_from_table(table, all, opt->top).front();
      pooled.name = "all";
      groups.push_back(std::move(pooled));
    }
    if (opt->json) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& g : groups) out.push_back(group_json(g));
      std::cout << nlohmann::json{{"groups", out}}.dump() << "\n";
      return;
    }
    print_counts(groups, opt->columns.value);
  });
}

}  // namespace ms::cli
