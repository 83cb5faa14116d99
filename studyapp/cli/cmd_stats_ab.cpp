// modalstudy stats ab: A/B blocks per group: proportion correct, exact binomial tests, d' (2AFC, ABX,
// yes-no, same-different), preference counts (analysis/ab_summary.hpp).
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <map>

#include "analysis/stats/ab_summary.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

namespace {

const std::map<std::string, AbTask> kTasks{{"2afc", AbTask::two_afc},
                                           {"abx", AbTask::abx},
                                           {"yesno", AbTask::yes_no},
                                           {"same-different", AbTask::same_different},
                                           {"preference", AbTask::preference}};

nlohmann::json summary_json(const AbSummary& s, AbTask task, const std::vector<std::string>& options) {
  nlohmann::json g = {{"group", s.group}, {"n", s.n}};
  if (task == AbTask::two_afc || task == AbTask::abx) {
    g.update({{"correct", s.correct}, {"pc", s.pc}, {"p_above_chance", s.above_chance.p},
              {"p_two_sided", s.two_sided.p}, {"ci_low", s.two_sided.ci_low}, {"ci_high", s.two_sided.ci_high},
              {"dprime", s.dprime}});
  } else if (task == AbTask::yes_no || task == AbTask::same_different) {
    g.update({{"hits", s.hits}, {"signal_trials", s.signal_trials}, {"false_alarms", s.false_alarms},
              {"noise_trials", s.noise_trials}, {"hit_rate", s.hit_rate}, {"false_alarm_rate", s.false_alarm_rate},
              {"dprime", s.dprime}});
    if (s.criterion_c) g["criterion_c"] = *s.criterion_c;
    if (s.criterion_k) g["criterion_k"] = *s.criterion_k;
  }
  if (const auto& p = s.preference) {
    g.update({{"prefer", {{options[0], p->first}, {options[1], p->second}}}, {"ties", p->ties}});
    if (p->test)
      g.update({{"proportion_first", p->test->proportion}, {"p", p->test->p}, {"ci_low", p->test->ci_low},
                {"ci_high", p->test->ci_high}});
  }
  if (const auto& t = s.score)
    g["score"] = {{"mean", t->mean_diff}, {"t", num_json(t->t)}, {"df", t->df}, {"p", num_json(t->p)},
                  {"ci_low", num_json(t->ci_low)}, {"ci_high", num_json(t->ci_high)}};
  return g;
}

}  // namespace

void register_stats_ab(CLI::App& group) {
  struct Options {
    std::string data, task = "2afc";
    AbColumns columns;
    std::vector<std::string> options;
    double chance = 0.5, conf_level = 0.95;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "ab", "A/B blocks: proportion correct, exact binomial test, d' (2AFC, ABX, yes-no, same-different), preference");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  AbColumns& c = opt->columns;
  cmd->add_option("data", opt->data, "Tidy CSV, one row per trial")->required();
  cmd->add_option("--task", opt->task, "2afc | abx | yesno | same-different | preference")
      ->check(CLI::IsMember({"2afc", "abx", "yesno", "same-different", "preference"}))
      ->capture_default_str();
  cmd->add_option("--by", c.by, "Column(s) to group by (e.g. participant, condition)");
  cmd->add_option("--correct", c.correct, "2afc/abx: column saying whether the answer was correct");
  cmd->add_option("--stimulus", c.stimulus, "yesno/same-different: column of the presented trial type");
  cmd->add_option("--response", c.response, "yesno/same-different: column of the answer");
  cmd->add_option("--target", c.target, "Stimulus value of signal trials (default: signal | different)");
  cmd->add_option("--yes", c.yes, "Response value meaning yes/different (default: yes | different)");
  cmd->add_option("--choice", c.choice, "preference: column of the chosen option");
  cmd->add_option("--options", opt->options, "preference: the two options, comma separated; other values are ties");
  cmd->add_option("--score", c.score, "preference: column of a graded score (e.g. -3..+3), tested against 0");
  cmd->add_option("--chance", opt->chance, "Chance proportion for 2afc/abx")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--conf-level", opt->conf_level, "Confidence level")->check(CLI::Range(0.5, 0.9999));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    const AbTask task = kTasks.at(opt->task);
    AbColumns columns = opt->columns;
    auto need = [&](const std::string& v, const char* flag) {
      if (v.empty()) throw InputError(SourceLocation{}, "--task " + opt->task + " needs " + flag + " COL");
    };
    if (task == AbTask::two_afc || task == AbTask::abx) need(columns.correct, "--correct");
    if (task == AbTask::yes_no || task == AbTask::same_different) {
      need(columns.stimulus, "--stimulus");
      need(columns.response, "--response");
    }
    const AbSummaryOptions so{opt->chance, opt->conf_level, split_commas(opt->options)};
    if (task == AbTask::preference) {
      if (columns.choice.empty() && columns.score.empty())
        throw InputError(SourceLocation{}, "--task preference needs --choice COL and/or --score COL");
      if (!columns.choice.empty() && so.options.size() != 2)
        throw InputError(SourceLocation{}, "--options: name exactly the two options, e.g. --options A,B");
    }
    if (columns.target.empty()) columns.target = task == AbTask::yes_no ? "signal" : "different";
    if (columns.yes.empty()) columns.yes = task == AbTask::yes_no ? "yes" : "different";
    nlohmann::json groups = nlohmann::json::array();
    bool corrected_any = false;
    for (const AbTrials& trials : ab_trials_from_table(table, task, columns)) {
      const AbSummary s = ab_summary(trials, task, so);
      corrected_any |= s.rates_corrected;
      groups.push_back(summary_json(s, task, so.options));
    }
    std::vector<std::string> notices;
    if (corrected_any)
      notices.push_back("rates of 0 or 1 were moved to 1/(2N) or 1 - 1/(2N) for d' (Macmillan & Kaplan 1985)");
    print_notices(notices, opt->data);
    if (opt->json) {
      std::cout << nlohmann::json{{"task", opt->task}, {"groups", groups}, {"notices", notices}}.dump() << "\n";
      return;
    }
    std::printf("%s: %zu group(s)\n", opt->task.c_str(), groups.size());
    for (const auto& g : groups) {
      std::printf("%s (n = %zu)\n", g["group"].get<std::string>().empty() ? "all" : g["group"].get<std::string>().c_str(),
                  g["n"].get<std::size_t>());
      for (const auto& [key, value] : g.items())
        if (key != "group" && key != "n") std::printf("  %-18s %s\n", key.c_str(), value.dump().c_str());
    }
  });
}

}  // namespace ms::cli
