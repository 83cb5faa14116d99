// modalstudy stats anova: repeated-measures ANOVA (analysis/stats/rm_anova.hpp) of a tidy CSV, with
// post-hoc pairwise t-tests (analysis/stats/posthoc.hpp) for the factors named by --posthoc.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "analysis/stats/posthoc.hpp"
#include "analysis/stats/rm_anova.hpp"
#include "analysis/stats/rm_data.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/posthoc_output.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {
void register_stats_anova(CLI::App& group) {
  struct Options {
    std::string data, dv, subject;
    std::vector<std::string> within, between, posthoc;
    std::string p_adjust = "holm";
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "anova", "Repeated-measures ANOVA (type III; GG/HF corrections, Mauchly, ges/pes), as afex::aov_ez");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per observation")->required();
  cmd->add_option("--dv", opt->dv, "Column of the dependent variable (numeric)")->required();
  cmd->add_option("--subject", opt->subject, "Column identifying the subject (listener)")->required();
  cmd->add_option("--within", opt->within, "Within-subject factor columns, comma separated")->required();
  cmd->add_option("--between", opt->between, "Between-subject factor column(s)");
  cmd->add_option("--posthoc", opt->posthoc, "Pairwise t-tests between the levels of these factors, comma separated");
  cmd->add_option("--p-adjust", opt->p_adjust, "Adjustment of the post-hoc p values over each factor's pairs")
      ->check(CLI::IsMember({"holm", "bonferroni", "none"}));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    std::vector<std::string> notices;
    const RmColumns columns{opt->dv, opt->subject, split_commas(opt->within), split_commas(opt->between)};
    const RmData data = rm_data_from_table(table, columns, notices);
    const RmAnova a = located(opt->data, "column '" + opt->dv + "'", [&] { return rm_anova(data); });
    std::vector<Posthoc> posthoc;
    for (const std::string& factor : split_commas(opt->posthoc)) {
      const bool in_design = std::count(columns.within.begin(), columns.within.end(), factor) +
                                 std::count(columns.between.begin(), columns.between.end(), factor) > 0;
      if (!in_design)
        throw InputError(SourceLocation{opt->data, 0, 0},
                         "--posthoc '" + factor + "' is not one of the --within or --between factors");
      posthoc.push_back(located(opt->data, "--posthoc '" + factor + "'",
                                [&] { return pairwise_t_tests(data, factor, p_adjust_from_name(opt->p_adjust)); }));
    }
    print_notices(notices, opt->data);
    if (opt->json) {
      nlohmann::json effects = nlohmann::json::array();
      for (const auto& e : a.effects)
        effects.push_back({{"effect", e.name},      {"df1", e.df1},
                           {"df2", e.df2},          {"F", num_json(e.F)},
                           {"p", num_json(e.p)},    {"eps_gg", opt_json(e.eps_gg)},
                           {"p_gg", num_json(e.p_gg)}, {"eps_hf", opt_json(e.eps_hf)},
                           {"p_hf", num_json(e.p_hf)}, {"ges", num_json(e.ges)},
                           {"pes", num_json(e.pes)}, {"mauchly_w", opt_json(e.mauchly_w)},
                           {"mauchly_p", opt_json(e.mauchly_p)}, {"ss", e.ss},
                           {"ss_error", e.ss_error}});
      nlohmann::json pairs = nlohmann::json::array();
      for (const auto& h : posthoc) pairs.push_back(posthoc_json(h));
      std::cout << nlohmann::json{{"effects", effects}, {"n_subjects", a.n_subjects}, {"posthoc", pairs},
                                  {"notices", notices}}
                       .dump()
                << "\n";
      return;
    }
    std::printf("Repeated-measures ANOVA of %s (%zu subjects; type III SS)\n", opt->dv.c_str(), a.n_subjects);
    std::printf("%-24s %5s %6s %10s %8s %7s %7s %7s\n", "Effect", "Df1", "Df2", "F value", "Pr(>F)", "GG eps",
                "HF eps", "ges");
    for (const auto& e : a.effects)
      std::printf("%-24s %5.0f %6.0f %10.4g %8s %7s %7s %7.4f\n", e.name.c_str(), e.df1, e.df2, e.F,
                  fmt_p(e.p).c_str(), e.eps_gg ? fmt("%.4f", *e.eps_gg).c_str() : "",
                  e.eps_hf ? fmt("%.4f", *e.eps_hf).c_str() : "", e.ges);
    bool any_mauchly = false;
    for (const auto& e : a.effects) any_mauchly |= e.mauchly_w.has_value();
    if (any_mauchly) {
      std::printf("\nMauchly's test for sphericity\n%-24s %10s %8s\n", "Effect", "W", "p");
      for (const auto& e : a.effects)
        if (e.mauchly_w) std::printf("%-24s %10.5f %8s\n", e.name.c_str(), *e.mauchly_w, fmt_p(*e.mauchly_p).c_str());
    }
    for (const auto& h : posthoc) print_posthoc(h);
  });
}

}  // namespace ms::cli
