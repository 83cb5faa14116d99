// modalstudy stats adjust: a method-of-adjustment study as Sterling et al. 2019 report their hand-tuning
// (section 1.3.2; analysis/stats/adjust_summary.hpp): per object, the time taken and the sounds played
// per answer as box summaries (Fig. 1.11), pooled per --group level; per tuned parameter the values
// chosen (median, quartiles, whiskers, mean, sd: Fig. 1.10's spread) and, where the table states the
// target's true value (adjust.csv's `truth`), the log ratio log10(chosen / true). Reads the export's
// adjust.csv as written: `modalstudy stats adjust adjust.csv --object object --group section`.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "analysis/stats/adjust_summary.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

namespace {

nlohmann::json box_json(const BoxSummary& b) {
  return {{"n", b.n}, {"lower_whisker", num_json(b.lower_whisker)}, {"q1", num_json(b.q1)},
          {"median", num_json(b.median)}, {"q3", num_json(b.q3)}, {"upper_whisker", num_json(b.upper_whisker)},
          {"outliers", b.outliers}};
}

// "lo [q1 med q3] hi" and the outliers, in `digits` significant digits.
std::string box_text(const BoxSummary& b, int digits) {
  std::string s = format_g(b.lower_whisker, digits) + " [" + format_g(b.q1, digits) + " " + format_g(b.median, digits) +
                  " " + format_g(b.q3, digits) + "] " + format_g(b.upper_whisker, digits);
  if (!b.outliers.empty()) {
    s += "  o";
    for (double v : b.outliers) s += " " + format_g(v, digits);
  }
  return s;
}

void print_summary(const AdjustSummary& s) {
  int gw = 5, ow = 13;  // column widths: the longest group and object names
  for (const AdjustObject& o : s.objects) gw = std::max(gw, int(o.group.size())), ow = std::max(ow, int(o.object.size()));
  std::printf("Time (s) and sounds played per answer: lower whisker [q1 median q3] upper whisker, o outliers\n");
  std::printf("%-*s %-*s %4s  %-38s %s\n", gw, "group", ow, "object", "n", "time (s)", "sounds played");
  for (const AdjustObject& o : s.objects)
    std::printf("%-*s %-*s %4zu  %-38s %s\n", gw, o.group.c_str(), ow, o.object.c_str(), o.time_s.n,
                box_text(o.time_s, 3).c_str(), box_text(o.plays, 3).c_str());
  for (const AdjustGroup& g : s.groups)
    std::printf("%-*s %-*s %4zu  %-38s %s\n", gw, g.group.c_str(), ow, "(all objects)", g.time_s.n,
                box_text(g.time_s, 3).c_str(), box_text(g.plays, 3).c_str());
  std::printf("\nChosen values: median [q1, q3], mean, sd; error log10(chosen / true): median, mean, rms\n");
  std::printf("%-*s %-*s %-24s %4s  %-34s %10s %10s  %10s  %8s %8s %8s\n", gw, "group", ow, "object", "key", "n",
              "median [q1, q3]", "mean", "sd", "true", "median", "mean", "rms");
  for (const AdjustObject& o : s.objects)
    for (const AdjustParameter& p : o.parameters) {
      const std::string spread = format_g(p.chosen.median, 4) + " [" + format_g(p.chosen.q1, 4) + ", " +
                                 format_g(p.chosen.q3, 4) + "]";
      std::string error = "-";
      if (p.log10_ratio)
        error = fmt("%8.3f", p.log10_ratio->median) + " " + fmt("%8.3f", p.log10_ratio_mean) + " " +
                fmt("%8.3f", p.log10_ratio_rms) +
                (p.not_positive ? "  (" + std::to_string(p.not_positive) + " not positive, left out)" : "");
      std::printf("%-*s %-*s %-24s %4zu  %-34s %10s %10s  %10s  %s\n", gw, o.group.c_str(), ow, o.object.c_str(),
                  p.key.c_str(), p.chosen.n, spread.c_str(), format_g(p.mean, 4).c_str(), format_g(p.sd, 3).c_str(),
                  p.truth ? format_g(*p.truth, 4).c_str() : "-", error.c_str());
    }
}

nlohmann::json summary_json(const AdjustSummary& s) {
  nlohmann::json objects = nlohmann::json::array(), groups = nlohmann::json::array();
  for (const AdjustObject& o : s.objects) {
    nlohmann::json params = nlohmann::json::array();
    for (const AdjustParameter& p : o.parameters)
      params.push_back({{"key", p.key}, {"chosen", box_json(p.chosen)}, {"mean", num_json(p.mean)}, {"sd", num_json(p.sd)},
                        {"truth", opt_json(p.truth)},
                        {"log10_ratio", p.log10_ratio ? box_json(*p.log10_ratio) : nlohmann::json()},
                        {"log10_ratio_mean", p.log10_ratio ? num_json(p.log10_ratio_mean) : nlohmann::json()},
                        {"log10_ratio_rms", p.log10_ratio ? num_json(p.log10_ratio_rms) : nlohmann::json()},
                        {"not_positive", p.not_positive}});
    objects.push_back({{"group", o.group}, {"object", o.object}, {"time_s", box_json(o.time_s)},
                       {"plays", box_json(o.plays)}, {"parameters", params}});
  }
  for (const AdjustGroup& g : s.groups)
    groups.push_back({{"group", g.group}, {"time_s", box_json(g.time_s)}, {"plays", box_json(g.plays)}});
  return {{"objects", objects}, {"groups", groups}};
}

}  // namespace

void register_stats_adjust(CLI::App& group) {
  struct Options {
    std::string data;
    AdjustColumns columns;
    std::string truth = "truth";
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "adjust", "Method of adjustment (Sterling 2019's hand-tuning): time, sounds played, chosen values, error vs truth");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per slider of an answer (the export's adjust.csv)")->required();
  cmd->add_option("--object", opt->columns.object, "Column naming what was tuned")->capture_default_str();
  cmd->add_option("--group", opt->columns.group, "Column whose levels are summarised apart and pooled (e.g. section)");
  cmd->add_option("--answer", opt->columns.answer, "Columns identifying one answer (its rows share plays and rt_ms)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--key", opt->columns.key, "Column of the tuned parameter")->capture_default_str();
  cmd->add_option("--value", opt->columns.value, "Column of the value chosen")->capture_default_str();
  cmd->add_option("--plays", opt->columns.plays, "Column of the sounds played per answer")->capture_default_str();
  cmd->add_option("--rt", opt->columns.rt_ms, "Column of the answer's time in ms")->capture_default_str();
  auto* truth = cmd->add_option("--truth", opt->truth,
                                "Column of the target's true value (NA where unknown); used when present, required "
                                "when given")
                    ->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in, truth] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    AdjustColumns columns = opt->columns;
    columns.truth = truth->count() > 0 || table.has_column(opt->truth) ? opt->truth : "";
    const AdjustSummary s = adjust_summary(table, columns);
    if (opt->json) std::cout << summary_json(s).dump() << "\n";
    else print_summary(s);
  });
}

}  // namespace ms::cli
