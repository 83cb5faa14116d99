// modalstudy stats ab: A/B blocks per group: proportion correct, exact binomial tests, d' (2AFC, ABX,
// yes-no, same-different), preference counts (analysis/ab_summary.hpp).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
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
  if (const auto& sc = s.score) {
    const auto& t = sc->test;
    const double none = std::numeric_limits<double>::quiet_NaN();
    g["score"] = {{"n", sc->n}, {"mean", sc->mean}, {"sd", num_json(sc->sd)}, {"t", num_json(t ? t->t : none)},
                  {"df", num_json(t ? t->df : none)}, {"p", num_json(t ? t->p : none)},
                  {"ci_low", num_json(t ? t->ci_low : none)}, {"ci_high", num_json(t ? t->ci_high : none)},
                  {"favours", favoured_side(*sc) == 0 ? "neither" : favoured_side(*sc) > 0 ? "second" : "first"}};
    if (options.size() == 2 && favoured_side(*sc) != 0) g["score"]["favours"] = options[favoured_side(*sc) > 0 ? 1 : 0];
  }
  return g;
}

std::string fixed(double v, const char* format = "%.3f") {
  if (!std::isfinite(v)) return "NA";
  char buf[40];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// The score of each group as one table: n, mean, sd (Fig. 5.2 / 5.3 of Skandalou & Ireland 2017), the
// t-test against 0 and the side the interval favours (Table 5.3).
void print_score_table(const nlohmann::json& groups, const std::string& column, const std::vector<std::string>& options,
                       bool per_subject, double conf_level) {
  const std::string first = options.size() == 2 ? options[0] : "the pair's first (A)";
  const std::string second = options.size() == 2 ? options[1] : "the pair's second (B)";
  std::printf("score '%s'%s: + favours %s, - favours %s; %zu group(s)\n", column.c_str(),
              per_subject ? " (each subject's mean per group)" : "", second.c_str(), first.c_str(), groups.size());
  std::size_t width = 5;
  for (const auto& g : groups) width = std::max(width, g["group"].get<std::string>().size());
  std::printf("%-*s %4s %7s %7s   %-19s %7s %5s %9s  %s\n", int(width), "group", "n", "mean", "sd",
              (fixed(100 * conf_level, "%.0f") + "% CI").c_str(), "t", "df", "p", "favours");
  const auto num = [](const nlohmann::json& v) { return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>(); };
  for (const auto& g : groups) {
    const auto& sc = g["score"];
    const std::string name = g["group"].get<std::string>().empty() ? "all" : g["group"].get<std::string>();
    const std::string ci = sc["ci_low"].is_null() ? "NA" : "[" + fixed(num(sc["ci_low"])) + ", " + fixed(num(sc["ci_high"])) + "]";
    std::printf("%-*s %4zu %7s %7s   %-19s %7s %5s %9s  %s\n", int(width), name.c_str(), sc["n"].get<std::size_t>(),
                fixed(num(sc["mean"])).c_str(), fixed(num(sc["sd"])).c_str(), ci.c_str(), fixed(num(sc["t"]), "%.2f").c_str(),
                fixed(num(sc["df"]), "%.0f").c_str(), fixed(num(sc["p"]), "%.3g").c_str(),
                sc["favours"].get<std::string>() == "neither" ? "neither (both)" : sc["favours"].get<std::string>().c_str());
  }
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
  cmd->add_option("--by", c.by, "Column(s) to group by, comma separated or repeated (e.g. object,location)");
  cmd->add_option("--correct", c.correct, "2afc/abx: column saying whether the answer was correct");
  cmd->add_option("--stimulus", c.stimulus, "yesno/same-different: column of the presented trial type");
  cmd->add_option("--response", c.response, "yesno/same-different: column of the answer");
  cmd->add_option("--target", c.target, "Stimulus value of signal trials (default: signal | different)");
  cmd->add_option("--yes", c.yes, "Response value meaning yes/different (default: yes | different)");
  cmd->add_option("--choice", c.choice, "preference: column of the chosen option");
  cmd->add_option("--options", opt->options,
                  "preference: the two options, comma separated (first, second); other choices are ties. With --score "
                  "they name the sides: - favours the first, + the second");
  cmd->add_option("--score", c.score,
                  "preference: column of a graded score (e.g. -3..+3): n, mean, sd and the t-test against 0 per group; "
                  "for an exported ab.csv use response_oriented (the answer turned to the protocol's written pair)");
  cmd->add_option("--subject", c.subject,
                  "with --score: average each subject's scores per group first (e.g. participant), so n counts subjects");
  cmd->add_option("--chance", opt->chance, "Chance proportion for 2afc/abx")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--conf-level", opt->conf_level, "Confidence level")->check(CLI::Range(0.5, 0.9999));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    const AbTask task = kTasks.at(opt->task);
    AbColumns columns = opt->columns;
    columns.by = split_commas(columns.by);  // --by object,location as --by object --by location
    auto need = [&](const std::string& v, const char* flag) {
      if (v.empty()) throw InputError(SourceLocation{}, "--task " + opt->task + " needs " + flag + " COL");
    };
    if (task == AbTask::two_afc || task == AbTask::abx) need(columns.correct, "--correct");
    if (task == AbTask::yes_no || task == AbTask::same_different) {
      need(columns.stimulus, "--stimulus");
      need(columns.response, "--response");
    }
    const AbSummaryOptions so{opt->chance, opt->conf_level, split_commas(opt->options)};
    if (!columns.subject.empty() && columns.score.empty())
      throw InputError(SourceLocation{}, "--subject averages scores: give --score COL too");
    if (task == AbTask::preference) {
      if (columns.choice.empty() && columns.score.empty())
        throw InputError(SourceLocation{}, "--task preference needs --choice COL and/or --score COL");
      if ((!columns.choice.empty() || !so.options.empty()) && so.options.size() != 2)
        throw InputError(SourceLocation{}, "--options: name exactly the two options, e.g. --options A,B");
    }

    if (columns.target.empty()) columns.target = task == AbTask::yes_no ? "signal" : "different";
    if (columns.yes.empty()) columns.yes = task == AbTask::yes_no ? "yes" : "different";
    nlohmann::json groups = nlohmann::json::array();
    bool corrected_any = false, averaged_any = false, untested_any = false;
    for (const AbTrials& trials : ab_trials_from_table(table, task, columns)) {
      const AbSummary s = ab_summary(trials, task, so);
      corrected_any |= s.rates_corrected;
      averaged_any |= trials.averaged;
      untested_any |= s.score && !s.score->test;
      groups.push_back(summary_json(s, task, so.options));
    }
    std::vector<std::string> notices;
    if (corrected_any)
      notices.push_back("rates of 0 or 1 were moved to 1/(2N) or 1 - 1/(2N) for d' (Macmillan & Kaplan 1985)");
    // An export's `response` is the answer in played order: A and B were drawn per trial.
    if (columns.score == "response" && table.has_column("response_oriented"))
      notices.push_back("'response' is each answer in the order played (A and B were drawn per trial), so its mean "
                        "tends to 0; 'response_oriented' turns it to the protocol's written pair");
    if (!columns.score.empty() && columns.subject.empty() && !averaged_any && table.has_column("participant")) {
      AbColumns by_participant;
      by_participant.by = columns.by;
      by_participant.score = columns.score;
      by_participant.subject = "participant";
      for (const AbTrials& t : ab_trials_from_table(table, task, by_participant))
        if (t.averaged) {
          notices.push_back("a participant has more than one score in a group: the rows are taken as independent; "
                            "--subject participant averages them first");
          break;
        }
    }
    if (averaged_any) notices.push_back("scores averaged per subject within each group (n counts subjects)");
    if (untested_any) notices.push_back("no t-test where a group has one score or all its scores are equal");
    print_notices(notices, opt->data);
    if (opt->json) {
      std::cout << nlohmann::json{{"task", opt->task}, {"groups", groups}, {"notices", notices}}.dump() << "\n";
      return;
    }
    if (task == AbTask::preference && !columns.score.empty()) {
      print_score_table(groups, columns.score, so.options, !columns.subject.empty(), opt->conf_level);
      if (columns.choice.empty()) return;
    }
    std::printf("%s: %zu group(s)\n", opt->task.c_str(), groups.size());
    for (const auto& g : groups) {
      std::printf("%s (n = %zu)\n", g["group"].get<std::string>().empty() ? "all" : g["group"].get<std::string>().c_str(),
                  g["n"].get<std::size_t>());
      for (const auto& [key, value] : g.items())
        if (key != "group" && key != "n" && key != "score") std::printf("  %-18s %s\n", key.c_str(), value.dump().c_str());
    }
  });
}

}  // namespace ms::cli
