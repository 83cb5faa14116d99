// modalstudy stats confusion: confusion matrix of an identification task (analysis/confusion.hpp);
// --compare a second file; --plot a heat map.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <set>

#include "analysis/stats/confusion.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "studyapp/plots/plots.hpp"

namespace ms::cli {

namespace {

nlohmann::json confusion_json(const Confusion& c) {
  const ChiSquareTest chi = chi2_independence(c.counts);
  nlohmann::json rec = nlohmann::json::array();
  for (double v : recall(c.counts)) rec.push_back(num_json(v));
  return {{"labels", c.labels},         {"n", c.counts.sum()},
          {"counts", matrix_json(c.counts)}, {"row_percent", matrix_json(row_percent(c.counts))},
          {"accuracy", accuracy(c.counts)},  {"recall", rec},
          {"kappa", num_json(cohen_kappa(c.counts))}, {"chi2", chi.chi2},
          {"chi2_df", chi.df},              {"chi2_p", num_json(chi.p)},
          {"chi2_yates", chi.yates}};
}

void print_confusion(const Confusion& c, const std::string& title) {
  const Eigen::MatrixXd pct = row_percent(c.counts);
  std::printf("%s (rows: truth, columns: response; row percent, n in the last column)\n%-14s", title.c_str(), "");
  for (const auto& l : c.labels) std::printf(" %10.10s", l.c_str());
  std::printf(" %7s\n", "n");
  for (Eigen::Index i = 0; i < pct.rows(); ++i) {
    std::printf("%-14.14s", c.labels[std::size_t(i)].c_str());
    for (Eigen::Index k = 0; k < pct.cols(); ++k) std::printf(" %10.1f", pct(i, k));
    std::printf(" %7.0f\n", c.counts.row(i).sum());
  }
  const ChiSquareTest chi = chi2_independence(c.counts);
  std::printf("accuracy %.4f, Cohen's kappa %.4f, chi2(%.0f) = %.4g, p = %s\n", accuracy(c.counts),
              cohen_kappa(c.counts), chi.df, chi.chi2, fmt("%.4g", chi.p).c_str());
}

// The interval of a recognition-rate difference: Newcombe's hybrid score interval (the default: good
// coverage for small counts) or the symmetric Wald interval of R's prop.test, with or without its
// continuity correction, as many published tables give it.
Interval difference_interval(const std::string& method, double x1, double n1, double x2, double n2,
                             double conf_level) {
  if (method == "wald") return wald_difference(x1, n1, x2, n2, false, conf_level);
  if (method == "wald-cc") return wald_difference(x1, n1, x2, n2, true, conf_level);
  return newcombe_difference(x1, n1, x2, n2, conf_level);
}

// The recognition-rate difference per label (first - second) with its interval.
nlohmann::json recall_differences(const Confusion& ca, const Confusion& cb, const std::string& interval,
                                  double conf_level) {
  nlohmann::json diffs = nlohmann::json::array();
  for (std::size_t i = 0; i < ca.labels.size(); ++i) {
    const Eigen::Index k = Eigen::Index(i);
    const double n1 = ca.counts.row(k).sum(), n2 = cb.counts.row(k).sum();
    if (n1 == 0 || n2 == 0) {
      diffs.push_back({{"label", ca.labels[i]}, {"diff", nullptr}, {"ci_low", nullptr}, {"ci_high", nullptr}});
      continue;
    }
    const Interval ci = difference_interval(interval, ca.counts(k, k), n1, cb.counts(k, k), n2, conf_level);
    diffs.push_back({{"label", ca.labels[i]}, {"diff", ca.counts(k, k) / n1 - cb.counts(k, k) / n2},
                     {"ci_low", ci.low}, {"ci_high", ci.high}});
  }
  return diffs;
}

void draw_heatmap(const std::string& path, const Confusion& c, const std::string& title, const std::string& truth,
                  const std::string& response) {
  const Eigen::MatrixXd pct = row_percent(c.counts);
  std::vector<std::vector<double>> rows(c.labels.size(), std::vector<double>(c.labels.size()));
  for (std::size_t i = 0; i < c.labels.size(); ++i)
    for (std::size_t k = 0; k < c.labels.size(); ++k) rows[i][k] = pct(Eigen::Index(i), Eigen::Index(k));
  plots::PlotOptions po;
  po.title = "Identification: " + title;
  po.x_label = "Response (" + response + ")";
  po.y_label = "Presented (" + truth + ")";
  plots::confusion_heatmap(path, c.labels, rows, po);
}

}  // namespace

void register_stats_confusion(CLI::App& group) {
  struct Options {
    std::string data, truth, response, compare, plot, interval = "newcombe";
    std::vector<std::string> labels, compare_where;
    double conf_level = 0.95;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "confusion", "Confusion matrix of an identification task: percent, accuracy, kappa, chi-square; --compare two");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per response")->required();
  cmd->add_option("--truth", opt->truth, "Column of the presented class")->required();
  cmd->add_option("--response", opt->response, "Column of the answered class")->required();
  cmd->add_option("--compare", opt->compare, "A second response file (same columns) to compare with");
  cmd->add_option("--compare-where", opt->compare_where,
                  "Rows of the --compare file to keep, COL=VALUE (repeatable), instead of --where's: two conditions "
                  "of one export, e.g. --where condition=recorded --compare identify.csv --compare-where "
                  "condition=synthesised")
      ->needs("--compare");
  cmd->add_option("--labels", opt->labels, "Class order, comma separated (default: sorted)");
  cmd->add_option("--conf-level", opt->conf_level, "Level of the recall-difference intervals")
      ->check(CLI::Range(0.5, 0.9999));
  cmd->add_option("--interval", opt->interval,
                  "Recall-difference interval: newcombe (hybrid score), wald or wald-cc (R's prop.test)")
      ->check(CLI::IsMember({"newcombe", "wald", "wald-cc"}));
  cmd->add_option("--plot", opt->plot, "Also draw the (first) matrix as a heat map: FILE.png or FILE.svg");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    if (!opt->plot.empty()) plots::check_output_path(opt->plot);
    std::vector<std::string> labels = split_commas(opt->labels);
    for (std::size_t i = 0; i < labels.size(); ++i)
      for (std::size_t k = 0; k < i; ++k)
        if (labels[i] == labels[k]) throw InputError(SourceLocation{}, "--labels: '" + labels[i] + "' listed twice");
    auto read = [&](const std::string& path, const StatsInput& filters) {
      return confusion_responses_from_table(read_stats_table(path, filters), opt->truth, opt->response, labels);
    };
    StatsInput compare_filters = *in;
    if (!opt->compare_where.empty()) compare_filters.where = opt->compare_where;
    const ConfusionResponses a = read(opt->data, *in);
    const ConfusionResponses b = opt->compare.empty() ? ConfusionResponses{} : read(opt->compare, compare_filters);
    if (labels.empty()) {
      std::set<std::string> all;
      for (const ConfusionResponses* r : {&a, &b}) {
        all.insert(r->truth.begin(), r->truth.end());
        all.insert(r->response.begin(), r->response.end());
      }
      labels.assign(all.begin(), all.end());
    }
    const Confusion ca = confusion_from_pairs(labels, a.truth, a.response);
    if (!opt->plot.empty()) draw_heatmap(opt->plot, ca, opt->data, opt->truth, opt->response);
    if (opt->compare.empty()) {
      if (opt->json) std::cout << confusion_json(ca).dump() << "\n";
      else print_confusion(ca, opt->data);
      return;
    }
    const Confusion cb = confusion_from_pairs(labels, b.truth, b.response);
    const double frob = frobenius_distance(row_percent(ca.counts), row_percent(cb.counts));
    const nlohmann::json diffs = recall_differences(ca, cb, opt->interval, opt->conf_level);
    if (opt->json) {
      nlohmann::json j = confusion_json(ca);
      j["compare"] = confusion_json(cb);
      j["compare"]["file"] = opt->compare;
      j["frobenius"] = frob;
      j["recall_diff"] = diffs;
      j["conf_level"] = opt->conf_level;
      j["interval"] = opt->interval;
      std::cout << j.dump() << "\n";
      return;
    }
    print_confusion(ca, opt->data);
    std::printf("\n");
    print_confusion(cb, opt->compare);
    std::printf("\nFrobenius norm of the difference of the row-percent matrices: %.4f\n", frob);
    const char* interval_name = opt->interval == "newcombe" ? "Newcombe" : opt->interval == "wald" ? "Wald" : "Wald (continuity-corrected)";
    std::printf("Recognition-rate difference (first - second), %.0f%% %s interval:\n", 100 * opt->conf_level,
                interval_name);
    for (const auto& d : diffs)
      if (!d["diff"].is_null())
        std::printf("  %-14s %+7.1f%%  [%+.1f%%, %+.1f%%]\n", d["label"].get<std::string>().c_str(),
                    100 * d["diff"].get<double>(), 100 * d["ci_low"].get<double>(), 100 * d["ci_high"].get<double>());
  });
}

}  // namespace ms::cli
