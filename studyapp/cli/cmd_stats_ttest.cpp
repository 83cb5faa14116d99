// modalstudy stats ttest: Welch, Student or paired two-sample t-test (analysis/t_test.hpp), as R's t.test.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "analysis/stats/t_test.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

void register_stats_ttest(CLI::App& group) {
  struct Options {
    std::string data, dv, group_col, subject;
    bool paired = false, student = false, json = false;
    double conf_level = 0.95;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand("ttest", "Two-sample t-test: Welch (default), Student or paired, as R's t.test");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per observation")->required();
  cmd->add_option("--dv", opt->dv, "Column of the dependent variable")->required();
  cmd->add_option("--group", opt->group_col, "Column with exactly two levels; the difference is first - second "
                                              "(in order of first appearance)")->required();
  cmd->add_flag("--paired", opt->paired, "Paired test; pairs matched by --subject");
  cmd->add_option("--subject", opt->subject, "Column identifying the subject (for --paired)");
  cmd->add_flag("--student", opt->student, "Pooled-variance (Student) test instead of Welch");
  cmd->add_option("--conf-level", opt->conf_level, "Confidence level of the interval")->check(CLI::Range(0.5, 0.9999));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    if (opt->paired && opt->subject.empty()) throw InputError(SourceLocation{}, "--paired needs --subject COL");
    const TidyCsv table = read_stats_table(opt->data, *in);
    const TTestSamples x =
        t_test_samples_from_table(table, TTestColumns{opt->dv, opt->group_col, opt->subject, opt->paired});
    std::vector<std::string> notices;
    if (x.averaged) notices.push_back("more than one observation per subject and level; aggregating with the mean");
    const TTest t = located(opt->data, "column '" + opt->dv + "'", [&] {
      return opt->paired    ? paired_t_test(x.first, x.second, opt->conf_level)
             : opt->student ? student_t_test(x.first, x.second, opt->conf_level)
                            : welch_t_test(x.first, x.second, opt->conf_level);
    });
    print_notices(notices, opt->data);
    const std::string method = opt->paired ? "paired" : opt->student ? "student" : "welch";
    if (opt->json) {
      std::cout << nlohmann::json{{"method", method},          {"levels", x.levels},
                                  {"n", {x.first.size(), x.second.size()}},
                                  {"t", num_json(t.t)},         {"df", num_json(t.df)},
                                  {"p", num_json(t.p)},         {"mean_diff", t.mean_diff},
                                  {"se", t.se},                 {"ci", {num_json(t.ci_low), num_json(t.ci_high)}},
                                  {"conf_level", t.conf_level}, {"notices", notices}}
                       .dump()
                << "\n";
      return;
    }
    std::printf("%s t-test of %s: %s - %s\n", method.c_str(), opt->dv.c_str(), x.levels[0].c_str(),
                x.levels[1].c_str());
    std::printf("t = %.4f, df = %.4g, p = %s\nmean difference %.6g, %.0f%% CI [%.6g, %.6g]\n", t.t, t.df,
                fmt("%.4g", t.p).c_str(), t.mean_diff, 100 * t.conf_level, t.ci_low, t.ci_high);
  });
}

}  // namespace ms::cli
