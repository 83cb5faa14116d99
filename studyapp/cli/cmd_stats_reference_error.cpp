// modalstudy stats reference-error: each dataset's error against a reference dataset's ratings
// (analysis/stats/reference_error.hpp), per subject, then a one-way repeated-measures ANOVA over the
// datasets and paired post-hoc t-tests: Sterling et al. 2019's Fig. 1.15 in one call, per attribute.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>

#include "analysis/stats/reference_error.hpp"
#include "analysis/stats/rm_anova.hpp"
#include "studyapp/cli/posthoc_output.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

void register_stats_reference_error(CLI::App& group) {
  struct Options {
    std::string data, by, p_adjust = "holm";
    ReferenceErrorColumns columns{"value", "participant", "dataset", "", {}};
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "reference-error",
      "Mean absolute error of each dataset's ratings against a reference dataset's, per subject, with a "
      "one-way repeated-measures ANOVA and paired post-hoc t-tests (Sterling et al. 2019, Fig. 1.15)");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one rating per row (e.g. the export's rating.csv)")->required();
  cmd->add_option("--reference", opt->columns.reference, "The dataset the others are compared with (e.g. rec)")
      ->required();
  cmd->add_option("--match", opt->columns.match, "Columns naming the same sound in every dataset, comma separated")
      ->delimiter(',')
      ->required();
  cmd->add_option("--dataset", opt->columns.dataset, "Column of the dataset")->capture_default_str();
  cmd->add_option("--dv", opt->columns.dv, "Column of the rating")->capture_default_str();
  cmd->add_option("--subject", opt->columns.subject, "Column of the subject")->capture_default_str();
  cmd->add_option("--by", opt->by, "One analysis per level of this column (e.g. attribute)");
  cmd->add_option("--p-adjust", opt->p_adjust, "Adjustment of the post-hoc p values")
      ->check(CLI::IsMember({"holm", "bonferroni", "none"}));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    // The analyses: the whole table, or one per level of --by (in order of first appearance).
    std::vector<std::pair<std::string, std::vector<std::size_t>>> parts;
    if (opt->by.empty()) {
      parts.push_back({"", {}});
      for (std::size_t r = 0; r < table.rows(); ++r) parts.back().second.push_back(r);
    } else {
      const std::size_t by = table.column(opt->by);
      for (std::size_t r = 0; r < table.rows(); ++r) {
        auto it = std::find_if(parts.begin(), parts.end(), [&](const auto& p) { return p.first == table.cell(r, by); });
        if (it == parts.end()) it = parts.insert(parts.end(), {table.cell(r, by), {}});
        it->second.push_back(r);
      }
    }
    nlohmann::json analyses = nlohmann::json::array();
    for (const auto& [level, rows] : parts) {
      const std::string what = level.empty() ? opt->data : opt->data + " (" + opt->by + " = " + level + ")";
      const RmData data = reference_error_design(table.keep_rows(rows), opt->columns);
      const RmAnova a = located(opt->data, what, [&] { return rm_anova(data); });
      const Posthoc h = located(opt->data, what, [&] {
        return pairwise_t_tests(data, opt->columns.dataset, p_adjust_from_name(opt->p_adjust));
      });
      const RmEffect& e = a.effects.front();
      const std::vector<std::string>& datasets = data.within.front().levels;
      if (opt->json) {
        nlohmann::json means = nlohmann::json::object();
        for (std::size_t j = 0; j < datasets.size(); ++j) means[datasets[j]] = data.cell_mean.col(Eigen::Index(j)).mean();
        analyses.push_back({{"by", level}, {"n_subjects", a.n_subjects}, {"mean_error", means},
                            {"F", num_json(e.F)}, {"df1", e.df1}, {"df2", e.df2}, {"p", num_json(e.p)},
                            {"eps_gg", opt_json(e.eps_gg)}, {"p_gg", num_json(e.p_gg)}, {"ges", num_json(e.ges)},
                            {"posthoc", posthoc_json(h)}});
        continue;
      }
      std::printf("%sError against '%s' (%zu subjects): ", level.empty() ? "" : (opt->by + " " + level + ": ").c_str(),
                  opt->columns.reference.c_str(), a.n_subjects);
      for (std::size_t j = 0; j < datasets.size(); ++j)
        std::printf("%s%s %.4g", j ? ", " : "", datasets[j].c_str(), data.cell_mean.col(Eigen::Index(j)).mean());
      std::printf("\n  F(%.0f, %.0f) = %.4g, p = %s (GG p = %s), ges %.4f\n", e.df1, e.df2, e.F, fmt_p(e.p).c_str(),
                  fmt_p(e.p_gg).c_str(), e.ges);
      print_posthoc(h);
      std::printf("\n");
    }
    if (opt->json) std::cout << nlohmann::json{{"reference", opt->columns.reference}, {"analyses", analyses}}.dump() << "\n";
  });
}

}  // namespace ms::cli
