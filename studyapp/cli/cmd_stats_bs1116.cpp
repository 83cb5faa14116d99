// modalstudy stats bs1116: difference grades per condition (mean, sd, t interval over assessors) and
// each assessor's screening figures (analysis/stats/bs1116.hpp), from the export's or webMUSHRA's
// bs1116.csv.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "analysis/stats/bs1116.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

namespace {

nlohmann::json bs1116_json(const Bs1116Result& res, double conf_level) {
  nlohmann::json assessors = nlohmann::json::array(), conds = nlohmann::json::array();
  for (const auto& a : res.assessors)
    assessors.push_back({{"subject", a.subject}, {"trials", a.trials}, {"positive", a.positive},
                         {"mean_diffgrade", a.mean}, {"t", opt_json(a.t)}, {"p_less", opt_json(a.p_less)}});
  for (const auto& c : res.conditions)
    conds.push_back({{"condition", c.condition}, {"n", c.n}, {"mean_diffgrade", c.mean},
                     {"sd", c.n >= 2 ? nlohmann::json(c.sd) : nullptr}, {"ci_low", opt_json(c.ci_low)},
                     {"ci_high", opt_json(c.ci_high)}});
  return {{"conf_level", conf_level}, {"assessors", assessors}, {"conditions", conds}, {"averaged", res.averaged}};
}

void print_bs1116(const Bs1116Result& res, double conf_level) {
  std::printf("BS.1116 difference grades (condition - hidden reference; 0 = no difference heard, -4 = very annoying)\n");
  std::printf("%-16s %5s %8s %8s   %2.0f%% CI\n", "Condition", "n", "mean", "sd", 100 * conf_level);
  for (const auto& c : res.conditions) {
    const std::string ci = c.ci_low ? "[" + fmt("%6.2f", *c.ci_low) + ", " + fmt("%6.2f", *c.ci_high) + "]" : "NA";
    std::printf("%-16s %5zu %8s %8s   %s\n", c.condition.c_str(), c.n, fmt("%.2f", c.mean).c_str(),
                c.n >= 2 ? fmt("%.2f", c.sd).c_str() : "NA", ci.c_str());
  }
  std::printf("\nAssessors (screening figures; nothing excluded): reference not identified = trials graded above it\n");
  std::printf("%-12s %7s %14s %8s %8s %10s\n", "Assessor", "trials", "not identified", "mean", "t", "p (<0)");
  for (const auto& a : res.assessors)
    std::printf("%-12s %7zu %14zu %8s %8s %10s\n", a.subject.c_str(), a.trials, a.positive, fmt("%.2f", a.mean).c_str(),
                a.t ? fmt("%.2f", *a.t).c_str() : "NA", a.p_less ? fmt_p(*a.p_less).c_str() : "NA");
}

}  // namespace

void register_stats_bs1116(CLI::App& group) {
  struct Options {
    std::string data;
    double conf_level = 0.95;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "bs1116", "BS.1116 (ITU-R BS.1116-3): difference grades per condition with CIs, assessors' screening figures");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "bs1116.csv, one row per trial (modalstudy export's or webMUSHRA's)")->required();
  cmd->add_option("--conf-level", opt->conf_level, "Confidence level")->check(CLI::Range(0.5, 0.9999));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const Bs1116Result res = bs1116_analyse(bs1116_from_table(read_stats_table(opt->data, *in)), opt->conf_level);
    std::vector<std::string> notices;
    if (res.averaged)
      notices.push_back(std::to_string(res.averaged) + " assessor/condition cells hold repeated trials; each "
                        "assessor's difference grades are averaged per condition first");
    print_notices(notices, opt->data);
    if (opt->json) std::cout << bs1116_json(res, opt->conf_level).dump() << "\n";
    else print_bs1116(res, opt->conf_level);
  });
}

}  // namespace ms::cli
