// modalstudy stats tokens: Table 2 of van den Doel et al. 2002 from the export's tokens.csv (one row
// per comparison of the adaptive token procedure): the tokens each participant distinguished in each
// sequence, with every sequence's ceiling (its number of tokens) and the counts' share of it
// (analysis/stats/distinguished_tokens.hpp). Counts of sequences with different ceilings are not on
// one scale, so no test across sequences is offered.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "analysis/stats/distinguished_tokens.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

namespace {

std::string ceiling_text(const TokensCondition& c) {
  return c.tokens_min == c.tokens_max ? std::to_string(c.tokens_min)
                                      : std::to_string(c.tokens_min) + "-" + std::to_string(c.tokens_max);
}

std::string percent(double share) { return fmt("%.0f", 100.0 * share) + " %"; }

void print_table(const TokensTable& t) {
  std::size_t width = 11;
  for (const auto& c : t.conditions) width = std::max(width, c.size());
  std::size_t first = 12;
  for (const auto& p : t.participants) first = std::max(first, p.size() + 1);
  const auto row = [&](const std::string& head, const auto& cell) {
    std::printf("%-*s", int(first), head.c_str());
    for (std::size_t k = 0; k < t.conditions.size(); ++k) std::printf(" %*s", int(width), cell(k).c_str());
    std::printf("\n");
  };
  std::printf("Tokens distinguished per participant and sequence (van den Doel et al. 2002, Table 2)\n");
  row("participant", [&](std::size_t k) { return t.conditions[k]; });
  for (std::size_t p = 0; p < t.participants.size(); ++p)
    row(t.participants[p], [&](std::size_t k) {
      if (t.series[p][k] == 0) return std::string("-");
      return format_g(t.count[p][k], 4) + (t.series[p][k] > 1 ? " (" + std::to_string(t.series[p][k]) + "x)" : "");
    });
  row("ceiling", [&](std::size_t k) { return ceiling_text(t.summary[k]); });
  row("median", [&](std::size_t k) { return format_g(t.summary[k].median, 4); });
  row("range", [&](std::size_t k) { return format_g(t.summary[k].min, 4) + "-" + format_g(t.summary[k].max, 4); });
  row("median share", [&](std::size_t k) { return percent(t.summary[k].median_share); });
  const bool equal = std::all_of(t.summary.begin(), t.summary.end(), [&](const TokensCondition& c) {
    return c.tokens_min == t.summary.front().tokens_min && c.tokens_max == t.summary.front().tokens_max;
  });
  if (!equal)
    std::printf("The sequences' ceilings differ: a count is bounded by its own sequence's number of tokens,\n"
                "so counts of different sequences are not comparable (compare the shares of the ceiling;\n"
                "a paired test of the counts would test the ceilings too).\n");
}

}  // namespace

void register_stats_tokens(CLI::App& group) {
  struct Options {
    std::string data;
    TokenColumns columns;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "tokens", "Adaptive token procedure (van den Doel et al. 2002, Exp. 2): tokens distinguished per participant "
                "and sequence, with each sequence's ceiling (Table 2)");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per comparison in presentation order (the export's tokens.csv)")
      ->required();
  cmd->add_option("--series", opt->columns.series, "Columns identifying one series")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--participant", opt->columns.participant, "Participant column (the table's rows)")->capture_default_str();
  cmd->add_option("--condition", opt->columns.condition,
                  "Column(s) naming a sequence (the table's columns), e.g. object,order from the stimuli's factors")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--reference", opt->columns.reference, "Column of the reference token's number of modes")->capture_default_str();
  cmd->add_option("--comparison", opt->columns.comparison, "Column of the compared token's number of modes")->capture_default_str();
  cmd->add_option("--different", opt->columns.different, "Column of the answer, 1 different / 0 same")->capture_default_str();
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    const TokensTable t = tokens_table(token_counts_from_table(table, opt->columns));
    if (!opt->json) return print_table(t);
    nlohmann::json conditions = nlohmann::json::array(), participants = nlohmann::json::array();
    for (const TokensCondition& c : t.summary)
      conditions.push_back({{"condition", c.name}, {"tokens_min", c.tokens_min}, {"tokens_max", c.tokens_max},
                            {"participants", c.participants}, {"median", c.median}, {"min", c.min}, {"max", c.max},
                            {"median_share", c.median_share}});
    for (std::size_t p = 0; p < t.participants.size(); ++p) {
      nlohmann::json cells = nlohmann::json::object();
      for (std::size_t k = 0; k < t.conditions.size(); ++k)
        if (t.series[p][k] > 0)
          cells[t.conditions[k]] = {{"distinguished", t.count[p][k]}, {"share", t.share[p][k]}, {"series", t.series[p][k]}};
      participants.push_back({{"participant", t.participants[p]}, {"cells", cells}});
    }
    std::cout << nlohmann::json{{"conditions", conditions}, {"participants", participants}}.dump() << "\n";
  });
}

}  // namespace ms::cli
