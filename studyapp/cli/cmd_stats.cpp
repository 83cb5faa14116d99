// modalstudy stats anova|ttest|confusion|mushra|ab|staircase|mds|magnitude ...: statistics of perceptual studies
// from tidy CSV files (one row per response). Each prints a table, or one JSON object with --json.
#include <nlohmann/json.hpp>

#include <array>
#include <cctype>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <optional>

#include "analysis/binomial_test.hpp"
#include "analysis/confusion.hpp"
#include "analysis/dissimilarity_matrix.hpp"
#include "analysis/magnitude_estimation.hpp"
#include "analysis/mds_cityblock.hpp"
#include "analysis/method_of_limits.hpp"
#include "analysis/quantile.hpp"
#include "studyapp/plots/plots.hpp"
#include "analysis/mds.hpp"
#include "analysis/mushra.hpp"
#include "analysis/rm_anova.hpp"
#include "analysis/rm_data.hpp"
#include "analysis/signal_detection.hpp"
#include "analysis/staircase.hpp"
#include "analysis/t_test.hpp"
#include "analysis/tidy_csv.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/csv.hpp"
#include "synthesis/input_error.hpp"

namespace ms::cli {

namespace {

nlohmann::json opt_json(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json num_json(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::vector<std::string> split_commas(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (const auto& a : args) {
    std::size_t start = 0;
    for (;;) {
      const auto comma = a.find(',', start);
      const std::string part = a.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (!part.empty()) out.push_back(part);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

std::string fmt(const char* f, double v) {
  if (!std::isfinite(v)) return "NA";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// p as published tables print it: "< .001" below 0.001, else three significant digits.
std::string fmt_p(double p) {
  if (!std::isfinite(p)) return "NA";
  if (p < 0.001) return "< .001";
  return fmt("%.3g", p);
}

// A statistic the data do not define (std::domain_error from the library) as one line naming the file.
template <class F>
auto located(const std::string& file, const std::string& what, F&& compute) {
  try {
    return compute();
  } catch (const std::domain_error& e) {
    throw InputError(SourceLocation{file, 0, 0}, what + ": " + e.what());
  }
}

void print_notices(const std::vector<std::string>& notices, const std::string& file) {
  for (const auto& n : notices) std::cerr << "notice: " << file << ": " << n << "\n";
}

void register_anova(CLI::App& group) {
  struct Options {
    std::string data, dv, subject;
    std::vector<std::string> within, between;
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
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    std::vector<std::string> notices;
    const RmData data = rm_data_from_table(
        table, RmColumns{opt->dv, opt->subject, split_commas(opt->within), split_commas(opt->between)}, notices);
    const RmAnova a = located(opt->data, "column '" + opt->dv + "'", [&] { return rm_anova(data); });
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
      std::cout << nlohmann::json{{"effects", effects}, {"n_subjects", a.n_subjects}, {"notices", notices}}.dump()
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
  });
}

void register_ttest(CLI::App& group) {
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
    const TidyCsv table = read_stats_table(opt->data, *in);
    const std::size_t col_dv = table.column(opt->dv), col_g = table.column(opt->group_col);
    if (opt->paired && opt->subject.empty()) throw InputError(SourceLocation{}, "--paired needs --subject COL");
    const std::size_t col_s = opt->paired ? table.column(opt->subject) : 0;
    if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
    std::vector<std::string> levels;
    std::vector<std::vector<double>> values(2);
    // Paired: mean per (subject, level), as afex aggregates; subjects in order of first appearance.
    std::vector<std::string> subjects;
    std::map<std::string, std::size_t> subject_index;
    std::vector<std::array<double, 2>> sums;
    std::vector<std::array<int, 2>> counts;
    std::vector<std::size_t> subject_row;
    for (std::size_t r = 0; r < table.rows(); ++r) {
      const double v = table.number(r, col_dv);
      const std::string& g = table.cell(r, col_g);
      std::size_t k = 0;
      while (k < levels.size() && levels[k] != g) ++k;
      if (k == levels.size()) {
        if (levels.size() == 2)
          throw InputError(table.where(r, col_g), "column '" + opt->group_col + "': a third level '" + g +
                                                      "' (a t-test compares exactly two)");
        levels.push_back(g);
      }
      if (!opt->paired) {
        values[k].push_back(v);
        continue;
      }
      auto [it, added] = subject_index.try_emplace(table.cell(r, col_s), subjects.size());
      if (added) {
        subjects.push_back(table.cell(r, col_s));
        sums.push_back({0, 0});
        counts.push_back({0, 0});
        subject_row.push_back(r);
      }
      sums[it->second][k] += v;
      counts[it->second][k] += 1;
    }
    if (levels.size() < 2)
      throw InputError(table.where(0, col_g), "column '" + opt->group_col + "' has a single level; need two");
    std::vector<std::string> notices;
    TTest t;
    if (opt->paired) {
      bool averaged = false;
      for (std::size_t s = 0; s < subjects.size(); ++s) {
        for (int k = 0; k < 2; ++k) {
          if (counts[s][std::size_t(k)] == 0)
            throw InputError(table.where(subject_row[s], col_s), "subject '" + subjects[s] + "' has no observation for " +
                                                                     opt->group_col + "=" + levels[std::size_t(k)]);
          averaged |= counts[s][std::size_t(k)] > 1;
          values[std::size_t(k)].push_back(sums[s][std::size_t(k)] / counts[s][std::size_t(k)]);
        }
      }
      if (averaged) notices.push_back("more than one observation per subject and level; aggregating with the mean");
      if (subjects.size() < 2) throw InputError(table.where(0, col_s), "a paired t-test needs at least two subjects");
      t = located(opt->data, "column '" + opt->dv + "'", [&] { return paired_t_test(values[0], values[1], opt->conf_level); });
    } else {
      for (int k = 0; k < 2; ++k)
        if (values[std::size_t(k)].size() < 2)
          throw InputError(table.where(0, col_g), "level '" + levels[std::size_t(k)] + "' has fewer than two observations");
      t = located(opt->data, "column '" + opt->dv + "'", [&] {
        return opt->student ? student_t_test(values[0], values[1], opt->conf_level)
                            : welch_t_test(values[0], values[1], opt->conf_level);
      });
    }
    print_notices(notices, opt->data);
    const std::string method = opt->paired ? "paired" : opt->student ? "student" : "welch";
    if (opt->json) {
      std::cout << nlohmann::json{{"method", method},          {"levels", levels},
                                  {"n", {values[0].size(), values[1].size()}},
                                  {"t", num_json(t.t)},         {"df", num_json(t.df)},
                                  {"p", num_json(t.p)},         {"mean_diff", t.mean_diff},
                                  {"se", t.se},                 {"ci", {num_json(t.ci_low), num_json(t.ci_high)}},
                                  {"conf_level", t.conf_level}, {"notices", notices}}
                       .dump()
                << "\n";
      return;
    }
    std::printf("%s t-test of %s: %s - %s\n", method.c_str(), opt->dv.c_str(), levels[0].c_str(), levels[1].c_str());
    std::printf("t = %.4f, df = %.4g, p = %s\nmean difference %.6g, %.0f%% CI [%.6g, %.6g]\n", t.t, t.df,
                fmt("%.4g", t.p).c_str(), t.mean_diff, 100 * t.conf_level, t.ci_low, t.ci_high);
  });
}

// Truth/response pairs of one identification file; labels checked against `labels` if given.
struct Responses {
  std::vector<std::string> truth, response;
};

Responses read_responses(const std::string& path, const std::string& truth_col, const std::string& response_col,
                         const std::vector<std::string>& labels, const StatsInput& in) {
  const TidyCsv table = read_stats_table(path, in);
  const std::size_t ct = table.column(truth_col), cr = table.column(response_col);
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  Responses r;
  for (std::size_t i = 0; i < table.rows(); ++i)
    for (std::size_t c : {ct, cr}) {
      const std::string& v = table.cell(i, c);
      if (v.empty()) throw InputError(table.where(i, c), "column '" + table.header()[c] + "': empty label");
      if (!labels.empty() && std::find(labels.begin(), labels.end(), v) == labels.end())
        throw InputError(table.where(i, c), "column '" + table.header()[c] + "': label '" + v + "' is not in --labels");
      (c == ct ? r.truth : r.response).push_back(v);
    }
  return r;
}

nlohmann::json matrix_json(const Eigen::MatrixXd& m) {
  nlohmann::json j = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index k = 0; k < m.cols(); ++k) row.push_back(m(i, k));
    j.push_back(row);
  }
  return j;
}

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

void register_confusion(CLI::App& group) {
  struct Options {
    std::string data, truth, response, compare, plot;
    std::vector<std::string> labels;
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
  cmd->add_option("--labels", opt->labels, "Class order, comma separated (default: sorted)");
  cmd->add_option("--conf-level", opt->conf_level, "Level of the recall-difference intervals")
      ->check(CLI::Range(0.5, 0.9999));
  cmd->add_option("--plot", opt->plot, "Also draw the (first) matrix as a heat map: FILE.png or FILE.svg");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    if (!opt->plot.empty()) plots::check_output_path(opt->plot);
    std::vector<std::string> labels = split_commas(opt->labels);
    for (std::size_t i = 0; i < labels.size(); ++i)
      for (std::size_t k = 0; k < i; ++k)
        if (labels[i] == labels[k]) throw InputError(SourceLocation{}, "--labels: '" + labels[i] + "' listed twice");
    const Responses a = read_responses(opt->data, opt->truth, opt->response, labels, *in);
    Responses b;
    if (!opt->compare.empty()) b = read_responses(opt->compare, opt->truth, opt->response, labels, *in);
    if (labels.empty()) {
      std::set<std::string> all;
      for (const Responses* r : {&a, static_cast<const Responses*>(&b)}) {
        all.insert(r->truth.begin(), r->truth.end());
        all.insert(r->response.begin(), r->response.end());
      }
      labels.assign(all.begin(), all.end());
    }
    const Confusion ca = confusion_from_pairs(labels, a.truth, a.response);
    if (!opt->plot.empty()) {
      const Eigen::MatrixXd pct = row_percent(ca.counts);
      std::vector<std::vector<double>> rows(labels.size(), std::vector<double>(labels.size()));
      for (std::size_t i = 0; i < labels.size(); ++i)
        for (std::size_t k = 0; k < labels.size(); ++k) rows[i][k] = pct(Eigen::Index(i), Eigen::Index(k));
      plots::PlotOptions po;
      po.title = "Identification: " + opt->data;
      po.x_label = "Response (" + opt->response + ")";
      po.y_label = "Presented (" + opt->truth + ")";
      plots::confusion_heatmap(opt->plot, labels, rows, po);
    }
    if (opt->compare.empty()) {
      if (opt->json) std::cout << confusion_json(ca).dump() << "\n";
      else print_confusion(ca, opt->data);
      return;
    }
    const Confusion cb = confusion_from_pairs(labels, b.truth, b.response);
    const double frob = frobenius_distance(row_percent(ca.counts), row_percent(cb.counts));
    nlohmann::json diffs = nlohmann::json::array();
    for (std::size_t i = 0; i < labels.size(); ++i) {
      const Eigen::Index k = Eigen::Index(i);
      const double n1 = ca.counts.row(k).sum(), n2 = cb.counts.row(k).sum();
      if (n1 == 0 || n2 == 0) {
        diffs.push_back({{"label", labels[i]}, {"diff", nullptr}, {"ci_low", nullptr}, {"ci_high", nullptr}});
        continue;
      }
      const Interval ci = newcombe_difference(ca.counts(k, k), n1, cb.counts(k, k), n2, opt->conf_level);
      diffs.push_back({{"label", labels[i]}, {"diff", ca.counts(k, k) / n1 - cb.counts(k, k) / n2},
                       {"ci_low", ci.low}, {"ci_high", ci.high}});
    }
    if (opt->json) {
      nlohmann::json j = confusion_json(ca);
      j["compare"] = confusion_json(cb);
      j["compare"]["file"] = opt->compare;
      j["frobenius"] = frob;
      j["recall_diff"] = diffs;
      j["conf_level"] = opt->conf_level;
      std::cout << j.dump() << "\n";
      return;
    }
    print_confusion(ca, opt->data);
    std::printf("\n");
    print_confusion(cb, opt->compare);
    std::printf("\nFrobenius norm of the difference of the row-percent matrices: %.4f\n", frob);
    std::printf("Recognition-rate difference (first - second), %.0f%% Newcombe interval:\n", 100 * opt->conf_level);
    for (const auto& d : diffs)
      if (!d["diff"].is_null())
        std::printf("  %-14s %+7.1f%%  [%+.1f%%, %+.1f%%]\n", d["label"].get<std::string>().c_str(),
                    100 * d["diff"].get<double>(), 100 * d["ci_low"].get<double>(), 100 * d["ci_high"].get<double>());
  });
}

// The first of `candidates` the table has, or the explicit choice when given.
std::size_t pick_column(const TidyCsv& table, const std::string& chosen, const std::vector<std::string>& candidates) {
  if (!chosen.empty()) return table.column(chosen);
  for (const auto& c : candidates)
    if (table.has_column(c)) return table.column(c);
  std::string names;
  for (const auto& c : candidates) names += (names.empty() ? "'" : " or '") + c + "'";
  throw InputError(SourceLocation{table.file(), 1, 1}, "missing column " + names);
}

nlohmann::json stat_json(const MushraStat& s) {
  return {{"condition", s.condition}, {"n", s.n}, {"mean", s.mean}, {"sd", s.n >= 2 ? nlohmann::json(s.sd) : nullptr},
          {"ci_low", opt_json(s.ci_low)}, {"ci_high", opt_json(s.ci_high)}, {"ci_past_scale", s.ci_past_scale}};
}

// "[ 61.20,  98.40]", "[ 80.10, 104.36]*" past the 0-100 scale, "NA" without an interval (n < 2).
std::string mushra_ci(const MushraStat& s) {
  if (!s.ci_low || !s.ci_high) return "NA";
  char buf[64];
  std::snprintf(buf, sizeof buf, "[%6.2f, %6.2f]%s", *s.ci_low, *s.ci_high, s.ci_past_scale ? "*" : "");
  return buf;
}

void register_mushra(CLI::App& group) {
  struct Options {
    std::string data, subject, item, condition, rating, plot;
    MushraOptions m;
    bool anchors_given = false, json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "mushra", "MUSHRA (ITU-R BS.1534-3): post-screening of assessors, means and 95% CIs per condition and item");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per rating (webMUSHRA column names accepted)")->required();
  cmd->add_option("--subject", opt->subject, "Assessor column (default: participant, subject or session_uuid)");
  cmd->add_option("--item", opt->item, "Item column (default: trial, item or trial_id)");
  cmd->add_option("--condition", opt->condition, "Condition column (default: condition or rating_stimulus)");
  cmd->add_option("--rating", opt->rating, "Rating column, 0-100 (default: rating or rating_score)");
  cmd->add_option("--reference", opt->m.reference, "Name of the hidden-reference condition")->capture_default_str();
  cmd->add_option("--anchor", opt->m.anchors, "Anchor condition(s) to check (default: conditions named anchor*)");
  cmd->add_flag("--screen-anchors", opt->m.screen_anchors,
                "Also exclude assessors rating an anchor above 90 in more than 15% of items");
  cmd->add_option("--conf-level", opt->m.conf_level, "Confidence level")->check(CLI::Range(0.5, 0.9999));
  cmd->add_option("--plot", opt->plot, "Also draw box plots with means and CIs: FILE.png or FILE.svg");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    if (!opt->plot.empty()) plots::check_output_path(opt->plot);
    const TidyCsv table = read_stats_table(opt->data, *in);
    const std::size_t cs = pick_column(table, opt->subject, {"participant", "subject", "session_uuid"});
    const std::size_t ci = pick_column(table, opt->item, {"trial", "item", "trial_id"});
    const std::size_t cc = pick_column(table, opt->condition, {"condition", "rating_stimulus"});
    const std::size_t cr = pick_column(table, opt->rating, {"rating", "rating_score"});
    if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
    std::vector<MushraRating> ratings;
    std::set<std::string> conditions;
    for (std::size_t r = 0; r < table.rows(); ++r) {
      const double v = table.number(r, cr);
      if (v < 0 || v > 100)
        throw InputError(table.where(r, cr), "column '" + table.header()[cr] + "': rating " + table.cell(r, cr) +
                                                 " outside the MUSHRA scale 0-100");
      for (std::size_t c : {cs, ci, cc})
        if (table.cell(r, c).empty()) throw InputError(table.where(r, c), "column '" + table.header()[c] + "': empty");
      ratings.push_back(MushraRating{table.cell(r, cs), table.cell(r, ci), table.cell(r, cc), v});
      conditions.insert(table.cell(r, cc));
    }
    auto where_condition = SourceLocation{table.file(), 1, 1};
    if (!conditions.count(opt->m.reference))
      throw InputError(where_condition, "no condition named '" + opt->m.reference +
                                            "' in column '" + table.header()[cc] + "' (name the hidden reference with --reference)");
    if (opt->m.anchors.empty()) {
      for (const auto& c : conditions)
        if (c.rfind("anchor", 0) == 0) opt->m.anchors.push_back(c);
    } else {
      for (const auto& a : opt->m.anchors)
        if (!conditions.count(a))
          throw InputError(where_condition, "--anchor: no condition named '" + a + "' in column '" + table.header()[cc] + "'");
    }
    const MushraResult res = mushra_analyse(ratings, opt->m);
    if (!opt->plot.empty()) {
      // Boxes of the ratings of the assessors kept by post-screening.
      std::set<std::string> kept;
      for (const auto& a : res.assessors)
        if (!a.excluded) kept.insert(a.subject);
      std::vector<std::string> names;
      std::vector<std::vector<double>> values;
      std::vector<double> means, lows, highs;
      for (const auto& c : res.conditions) {
        names.push_back(c.condition);
        values.emplace_back();
        for (const auto& r : ratings)
          if (r.condition == c.condition && kept.count(r.subject)) values.back().push_back(r.rating);
        means.push_back(c.n ? c.mean : std::nan(""));
        lows.push_back(c.ci_low.value_or(std::nan("")));
        highs.push_back(c.ci_high.value_or(std::nan("")));
      }
      plots::PlotOptions po;
      po.title = "MUSHRA: " + opt->data + " (" + std::to_string(res.included) + " assessors kept)";
      po.x_label = "Condition";
      po.y_label = "Rating (0-100)";
      plots::mushra_boxplot(opt->plot, names, values, means, lows, highs, po);
    }
    std::vector<std::string> notices;
    if (res.averaged)
      notices.push_back(std::to_string(res.averaged) +
                        " assessor/item/condition cells were rated more than once; their ratings are averaged");
    if (res.included == 0) notices.push_back("every assessor was excluded by post-screening; no statistics");
    std::size_t past = 0;
    for (const auto& c : res.conditions) past += c.ci_past_scale;
    for (const auto& it : res.items)
      for (const auto& c : it.conditions) past += c.ci_past_scale;
    if (past)
      notices.push_back(std::to_string(past) + " confidence interval(s) pass the 0-100 scale; reported as computed "
                        "(t interval, not clipped) and marked *");
    print_notices(notices, opt->data);
    if (opt->json) {
      nlohmann::json assessors = nlohmann::json::array(), conds = nlohmann::json::array(), items = nlohmann::json::array();
      for (const auto& a : res.assessors) {
        nlohmann::json checks = nlohmann::json::array();
        for (const auto& k : a.anchors)
          checks.push_back({{"anchor", k.anchor}, {"items", k.items}, {"above", k.above},
                            {"fraction", k.items ? nlohmann::json(double(k.above) / double(k.items)) : nullptr},
                            {"fails", k.fails}});
        assessors.push_back({{"subject", a.subject}, {"reference_items", a.reference_items},
                             {"reference_below", a.reference_below},
                             {"reference_fraction", a.reference_items ? nlohmann::json(double(a.reference_below) /
                                                                                        double(a.reference_items))
                                                                      : nullptr},
                             {"reference_fails", a.reference_fails}, {"anchor_checks", checks},
                             {"anchor_fails", a.anchor_fails}, {"excluded", a.excluded}});
      }
      for (const auto& c : res.conditions) conds.push_back(stat_json(c));
      for (const auto& it : res.items) {
        nlohmann::json ic = nlohmann::json::array();
        for (const auto& c : it.conditions) ic.push_back(stat_json(c));
        items.push_back({{"item", it.item}, {"conditions", ic}});
      }
      std::cout << nlohmann::json{{"reference", opt->m.reference}, {"anchors", opt->m.anchors},
                                  {"n_assessors", res.assessors.size()}, {"n_included", res.included},
                                  {"conf_level", opt->m.conf_level}, {"assessors", assessors},
                                  {"conditions", conds}, {"items", items}, {"notices", notices}}
                       .dump()
                << "\n";
      return;
    }
    std::printf("MUSHRA post-screening (ITU-R BS.1534-3): %zu of %zu assessors kept\n", res.included,
                res.assessors.size());
    for (const auto& a : res.assessors) {
      std::string why;
      if (a.reference_fails)
        why += "reference < 90 in " + std::to_string(a.reference_below) + "/" + std::to_string(a.reference_items) + " items";
      for (const auto& k : a.anchors)
        if (k.fails)
          why += (why.empty() ? "" : "; ") + k.anchor + " > 90 in " + std::to_string(k.above) + "/" +
                 std::to_string(k.items) + " items";
      if (!why.empty()) std::printf("  %-12s %s: %s\n", a.subject.c_str(), a.excluded ? "excluded" : "flagged", why.c_str());
    }
    std::printf("\n%-16s %5s %8s %8s %17s\n", "Condition", "n", "mean", "sd", "95% CI");
    for (const auto& c : res.conditions)
      std::printf("%-16s %5zu %8s %8s   %s\n", c.condition.c_str(), c.n, c.n ? fmt("%.2f", c.mean).c_str() : "NA",
                  c.n >= 2 ? fmt("%.2f", c.sd).c_str() : "NA", mushra_ci(c).c_str());
    std::printf("\nPer item (mean [95%% CI])\n");
    for (const auto& it : res.items) {
      std::printf("%s\n", it.item.c_str());
      for (const auto& c : it.conditions)
        std::printf("  %-14s %7s %s\n", c.condition.c_str(), c.n ? fmt("%.2f", c.mean).c_str() : "NA",
                    mushra_ci(c).c_str());
    }
    if (past) std::printf("* the interval passes the 0-100 scale (reported as computed, not clipped)\n");
  });
}

// Rows grouped by the value of an optional column, groups in order of first appearance.
std::vector<std::pair<std::string, std::vector<std::size_t>>> group_rows(const TidyCsv& table,
                                                                         const std::vector<std::string>& by) {
  std::vector<std::size_t> cols;
  for (const auto& b : by) cols.push_back(table.column(b));
  std::vector<std::pair<std::string, std::vector<std::size_t>>> groups;
  std::map<std::string, std::size_t> index;
  for (std::size_t r = 0; r < table.rows(); ++r) {
    std::string key;
    for (std::size_t c : cols) key += (key.empty() ? "" : "/") + table.cell(r, c);
    auto [it, added] = index.try_emplace(key, groups.size());
    if (added) groups.push_back({key, {}});
    groups[it->second].second.push_back(r);
  }
  return groups;
}

std::string lower_case(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool parse_correct(const TidyCsv& table, std::size_t r, std::size_t c) {
  const std::string v = lower_case(table.cell(r, c));
  if (v == "1" || v == "true" || v == "yes" || v == "correct") return true;
  if (v == "0" || v == "false" || v == "no" || v == "incorrect") return false;
  throw InputError(table.where(r, c), "column '" + table.header()[c] + "': expected 1/0, true/false, yes/no or "
                                      "correct/incorrect, got '" + table.cell(r, c) + "'");
}

void register_ab(CLI::App& group) {
  struct Options {
    std::string data, task = "2afc", correct, stimulus, response, target, yes, choice, score;
    std::vector<std::string> by, options;
    double chance = 0.5, conf_level = 0.95;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "ab", "A/B blocks: proportion correct, exact binomial test, d' (2AFC, ABX, yes-no, same-different), preference");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per trial")->required();
  cmd->add_option("--task", opt->task, "2afc | abx | yesno | same-different | preference")
      ->check(CLI::IsMember({"2afc", "abx", "yesno", "same-different", "preference"}))
      ->capture_default_str();
  cmd->add_option("--by", opt->by, "Column(s) to group by (e.g. participant, condition)");
  cmd->add_option("--correct", opt->correct, "2afc/abx: column saying whether the answer was correct");
  cmd->add_option("--stimulus", opt->stimulus, "yesno/same-different: column of the presented trial type");
  cmd->add_option("--response", opt->response, "yesno/same-different: column of the answer");
  cmd->add_option("--target", opt->target, "Stimulus value of signal trials (default: signal | different)");
  cmd->add_option("--yes", opt->yes, "Response value meaning yes/different (default: yes | different)");
  cmd->add_option("--choice", opt->choice, "preference: column of the chosen option");
  cmd->add_option("--options", opt->options, "preference: the two options, comma separated; other values are ties");
  cmd->add_option("--score", opt->score, "preference: column of a graded score (e.g. -3..+3), tested against 0");
  cmd->add_option("--chance", opt->chance, "Chance proportion for 2afc/abx")->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--conf-level", opt->conf_level, "Confidence level")->check(CLI::Range(0.5, 0.9999));
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
    auto need = [&](const std::string& v, const char* flag) {
      if (v.empty()) throw InputError(SourceLocation{}, "--task " + opt->task + " needs " + flag + " COL");
      return table.column(v);
    };
    std::vector<std::string> notices;
    nlohmann::json groups = nlohmann::json::array();
    const bool forced = opt->task == "2afc" || opt->task == "abx";
    const bool detection = opt->task == "yesno" || opt->task == "same-different";
    // Resolve columns before grouping so a missing one is reported first.
    std::size_t c_correct = 0, c_stim = 0, c_resp = 0, c_choice = 0, c_score = 0;
    if (forced) c_correct = need(opt->correct, "--correct");
    if (detection) {
      c_stim = need(opt->stimulus, "--stimulus");
      c_resp = need(opt->response, "--response");
    }
    std::vector<std::string> pref_options = split_commas(opt->options);
    if (opt->task == "preference") {
      if (opt->choice.empty() && opt->score.empty())
        throw InputError(SourceLocation{}, "--task preference needs --choice COL and/or --score COL");
      if (!opt->choice.empty()) {
        c_choice = table.column(opt->choice);
        if (pref_options.size() != 2)
          throw InputError(SourceLocation{}, "--options: name exactly the two options, e.g. --options A,B");
      }
      if (!opt->score.empty()) c_score = table.column(opt->score);
    }
    const std::string target = !opt->target.empty() ? opt->target : opt->task == "yesno" ? "signal" : "different";
    const std::string yes = !opt->yes.empty() ? opt->yes : opt->task == "yesno" ? "yes" : "different";
    bool corrected_any = false;
    for (const auto& [name, rows] : group_rows(table, opt->by)) {
      nlohmann::json g = {{"group", name}, {"n", rows.size()}};
      if (forced) {
        unsigned k = 0;
        for (std::size_t r : rows) k += parse_correct(table, r, c_correct);
        const unsigned n = unsigned(rows.size());
        const BinomialTest above = binomial_test(k, n, opt->chance, Alternative::greater, opt->conf_level);
        const BinomialTest two = binomial_test(k, n, opt->chance, Alternative::two_sided, opt->conf_level);
        const double pc = corrected_rate(k, n);
        corrected_any |= k == 0 || k == n;
        g.update({{"correct", k}, {"pc", double(k) / n}, {"p_above_chance", above.p}, {"p_two_sided", two.p},
                  {"ci_low", two.ci_low}, {"ci_high", two.ci_high},
                  {"dprime", opt->task == "2afc" ? dprime_2afc(pc) : dprime_abx(pc)}});
      } else if (detection) {
        double hits = 0, signal = 0, fas = 0, noise = 0;
        for (std::size_t r : rows) {
          const bool is_signal = table.cell(r, c_stim) == target;
          const bool said_yes = table.cell(r, c_resp) == yes;
          (is_signal ? signal : noise) += 1;
          (is_signal ? hits : fas) += said_yes;
        }
        if (signal == 0 || noise == 0)
          throw InputError(table.where(rows.front(), c_stim),
                           "group '" + name + "' needs both '" + target + "' trials and others in column '" +
                               table.header()[c_stim] + "'");
        corrected_any |= hits == 0 || hits == signal || fas == 0 || fas == noise;
        const double h = corrected_rate(hits, signal), f = corrected_rate(fas, noise);
        g.update({{"hits", hits}, {"signal_trials", signal}, {"false_alarms", fas}, {"noise_trials", noise},
                  {"hit_rate", hits / signal}, {"false_alarm_rate", fas / noise}});
        if (opt->task == "yesno") {
          g["dprime"] = dprime_yes_no(h, f);
          g["criterion_c"] = -(normal_quantile(h) + normal_quantile(f)) / 2;
        } else {
          const SameDifferent sd = dprime_same_different(h, f);
          g["dprime"] = sd.dprime;
          g["criterion_k"] = sd.criterion_k;
        }
      } else {
        if (!opt->choice.empty()) {
          unsigned a = 0, b = 0, ties = 0;
          for (std::size_t r : rows) {
            const std::string& v = table.cell(r, c_choice);
            if (v == pref_options[0]) ++a;
            else if (v == pref_options[1]) ++b;
            else ++ties;
          }
          g.update({{"prefer", {{pref_options[0], a}, {pref_options[1], b}}}, {"ties", ties}});
          if (a + b > 0) {
            const BinomialTest t = binomial_test(a, a + b, 0.5, Alternative::two_sided, opt->conf_level);
            g.update({{"proportion_first", t.proportion}, {"p", t.p}, {"ci_low", t.ci_low}, {"ci_high", t.ci_high}});
          }
        }
        if (!opt->score.empty()) {
          std::vector<double> scores, zeros;
          for (std::size_t r : rows) scores.push_back(table.number(r, c_score));
          zeros.assign(scores.size(), 0.0);
          if (scores.size() >= 2) {
            const TTest t = paired_t_test(scores, zeros, opt->conf_level);
            g["score"] = {{"mean", t.mean_diff}, {"t", num_json(t.t)}, {"df", t.df}, {"p", num_json(t.p)},
                          {"ci_low", num_json(t.ci_low)}, {"ci_high", num_json(t.ci_high)}};
          }
        }
      }
      groups.push_back(g);
    }
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

void register_staircase(CLI::App& group) {
  struct Options {
    std::string data, level, trial, next_level = "next_level";
    std::vector<std::string> track;
    std::size_t reversals = 0;
    bool log_scale = false, json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "staircase", "Adaptive-staircase thresholds per track: mean reversal level after the first two (as the protocol's)");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per trial")->required();
  cmd->add_option("--level", opt->level, "Column of the stimulus level presented")->required();
  cmd->add_option("--track", opt->track, "Column(s) identifying a track (e.g. participant, staircase)");
  cmd->add_option("--trial", opt->trial, "Column ordering the trials (default: file order)");
  cmd->add_option("--next-level", opt->next_level,
                  "Column of the level after each answer, so a reversal at a track's last trial counts (used when "
                  "present)")
      ->capture_default_str();
  cmd->add_option("--reversals", opt->reversals,
                  "Average the last K reversals (default: all but the first two, all when there are at most four)")
      ->check(CLI::Range(1, 1000));
  cmd->add_flag("--log", opt->log_scale, "Geometric mean (levels on a ratio scale)");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    const std::size_t cl = table.column(opt->level);
    const std::size_t ct = opt->trial.empty() ? 0 : table.column(opt->trial);
    const bool has_next = table.has_column(opt->next_level);
    const std::size_t cn = has_next ? table.column(opt->next_level) : 0;
    if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
    StaircaseOptions so;
    if (opt->reversals > 0) so.last_k = opt->reversals;
    so.log_scale = opt->log_scale;
    nlohmann::json tracks = nlohmann::json::array();
    std::vector<std::string> notices;
    if (!has_next)
      notices.push_back("no column '" + opt->next_level +
                        "' (the level after each answer): a reversal at a track's last trial is not counted");
    std::vector<double> thresholds;
    for (auto [name, rows] : group_rows(table, opt->track)) {
      if (!opt->trial.empty()) {
        std::vector<std::pair<double, std::size_t>> order;
        for (std::size_t r : rows) order.push_back({table.number(r, ct), r});
        std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = order[i].second;
      }
      std::vector<double> levels;
      for (std::size_t r : rows) {
        levels.push_back(table.number(r, cl));
        if (opt->log_scale && !(levels.back() > 0))
          throw InputError(table.where(r, cl), "column '" + opt->level + "': --log needs levels above 0");
      }
      std::optional<double> next;
      if (has_next) next = table.number(rows.back(), cn);
      const StaircaseThreshold t = staircase_threshold(levels, next, so);
      if (so.last_k && t.used < *so.last_k)
        notices.push_back("track '" + (name.empty() ? std::string("all") : name) + "' has " +
                          std::to_string(t.reversal_levels.size()) + " reversals, fewer than " +
                          std::to_string(*so.last_k));
      if (t.threshold) thresholds.push_back(*t.threshold);
      tracks.push_back({{"track", name}, {"trials", levels.size()}, {"reversal_levels", t.reversal_levels},
                        {"used", t.used}, {"threshold", opt_json(t.threshold)}, {"sd", opt_json(t.sd)}});
    }
    nlohmann::json overall = nullptr;
    if (thresholds.size() >= 2) {
      const MushraStat s = describe("threshold", thresholds, 0.95);
      overall = {{"n", s.n}, {"mean", s.mean}, {"sd", s.sd}, {"ci_low", opt_json(s.ci_low)}, {"ci_high", opt_json(s.ci_high)}};
    }
    print_notices(notices, opt->data);
    if (opt->json) {
      std::cout << nlohmann::json{{"reversals", so.last_k ? nlohmann::json(*so.last_k) : nlohmann::json("all but the first two")},
                                  {"log", opt->log_scale}, {"tracks", tracks}, {"overall", overall},
                                  {"notices", notices}}.dump()
                << "\n";
      return;
    }
    std::printf("%-20s %7s %10s %6s %12s\n", "Track", "trials", "reversals", "used", "threshold");
    for (const auto& t : tracks)
      std::printf("%-20s %7zu %10zu %6zu %12s\n", t["track"].get<std::string>().c_str(), t["trials"].get<std::size_t>(),
                  t["reversal_levels"].size(), t["used"].get<std::size_t>(),
                  t["threshold"].is_null() ? "NA" : fmt("%.4g", t["threshold"].get<double>()).c_str());
    if (!overall.is_null())
      std::printf("mean over tracks %.4g, 95%% CI [%.4g, %.4g]\n", overall["mean"].get<double>(),
                  overall["ci_low"].get<double>(), overall["ci_high"].get<double>());
  });
}

void register_mds(CLI::App& group) {
  struct Options {
    std::string data, method = "classical", output, plot;
    std::vector<std::string> pairs;
    int dims = 2, starts = 3;
    std::uint64_t seed = 1;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand("mds", "Multidimensional scaling of dissimilarities: classical, SMACOF, nonmetric");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Square dissimilarity matrix CSV (label column + one column per stimulus)")
      ->required();
  cmd->add_option("--dims", opt->dims, "Dimensions of the map")->check(CLI::Range(1, 10))->capture_default_str();
  cmd->add_option("--method", opt->method, "classical | smacof | nonmetric | cityblock (metric SMACOF, L1 distances)")
      ->check(CLI::IsMember({"classical", "smacof", "nonmetric", "cityblock"}))
      ->capture_default_str();
  cmd->add_option("--pairs", opt->pairs, "Read long form instead: FIRST,SECOND,VALUE columns (ratings averaged)");
  cmd->add_option("--starts", opt->starts, "Random starts besides the classical one (smacof, nonmetric)")
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--seed", opt->seed, "Seed of the random starts")->capture_default_str();
  cmd->add_option("-o,--output", opt->output, "Write the configuration as CSV (label, dim1, ...)");
  cmd->add_option("--plot", opt->plot, "Also draw the map (first two dimensions): FILE.png or FILE.svg");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    if (!opt->plot.empty()) {
      plots::check_output_path(opt->plot);
      if (opt->dims < 2) throw InputError(SourceLocation{"--plot", 0, 0}, "a map needs --dims 2 or more");
    }
    const TidyCsv table = read_stats_table(opt->data, *in);
    const std::vector<std::string> pairs = split_commas(opt->pairs);
    if (!opt->pairs.empty() && pairs.size() != 3)
      throw InputError(SourceLocation{}, "--pairs: give three columns FIRST,SECOND,VALUE");
    const DissimilarityMatrix d =
        pairs.empty() ? dissimilarity_from_square(table) : dissimilarity_from_pairs(table, pairs[0], pairs[1], pairs[2]);
    if (std::size_t(opt->dims) >= d.labels.size())
      throw InputError(SourceLocation{}, "--dims " + std::to_string(opt->dims) + ": need fewer dimensions than the " +
                                             std::to_string(d.labels.size()) + " stimuli");
    std::vector<std::string> notices;
    if (d.averaged_pairs)
      notices.push_back(std::to_string(d.averaged_pairs) + " pairs were rated more than once; ratings averaged");
    Eigen::MatrixXd points;
    nlohmann::json extra;
    if (opt->method == "classical") {
      const ClassicalMds c = classical_mds(d.values, opt->dims);
      points = c.points;
      std::vector<double> eig(c.eigenvalues.data(), c.eigenvalues.data() + c.eigenvalues.size());
      extra = {{"eigenvalues", eig}, {"stress1", stress1(d.values, points)}};
    } else {
      SmacofOptions o;
      o.dims = opt->dims;
      o.random_starts = opt->starts;
      o.seed = opt->seed;
      const SmacofResult r = opt->method == "smacof"      ? smacof(d.values, o)
                             : opt->method == "cityblock" ? smacof_cityblock(d.values, o)
                                                          : smacof_nonmetric(d.values, o);
      points = r.points;
      extra = {{"stress1", r.stress1}, {"raw_stress", r.raw_stress}, {"iterations", r.iterations},
               {"best_start", r.best_start}, {"starts", opt->starts + 1}, {"seed", opt->seed}};
    }
    if (!opt->output.empty()) {
      std::vector<std::string> header{"label"};
      for (int k = 0; k < opt->dims; ++k) header.push_back("dim" + std::to_string(k + 1));
      std::string csv = csv::line(header);
      for (std::size_t i = 0; i < d.labels.size(); ++i) {
        std::vector<std::string> cells{d.labels[i]};
        for (int k = 0; k < opt->dims; ++k) cells.push_back(fmt("%.17g", points(Eigen::Index(i), k)));
        csv += csv::line(cells);
      }
      write_file_atomically(opt->output, csv);
    }
    if (!opt->plot.empty()) {
      std::vector<plots::XY> xy;
      for (Eigen::Index i = 0; i < points.rows(); ++i) xy.push_back({points(i, 0), points(i, 1)});
      plots::PlotOptions po;
      po.title = "MDS (" + opt->method + "): " + opt->data + ", stress-1 " + fmt("%.3f", extra["stress1"].get<double>());
      po.x_label = "Dimension 1";
      po.y_label = "Dimension 2";
      plots::mds_map(opt->plot, xy, d.labels, po);
    }
    print_notices(notices, opt->data);
    if (opt->json) {
      nlohmann::json j = {{"method", opt->method}, {"dims", opt->dims}, {"labels", d.labels},
                          {"points", matrix_json(points)}, {"notices", notices}};
      j.update(extra);
      std::cout << j.dump() << "\n";
      return;
    }
    std::printf("%s MDS of %zu stimuli in %d dimensions: stress-1 = %.4f\n", opt->method.c_str(), d.labels.size(),
                opt->dims, extra["stress1"].get<double>());
    for (std::size_t i = 0; i < d.labels.size(); ++i) {
      std::printf("%-20s", d.labels[i].c_str());
      for (int k = 0; k < opt->dims; ++k) std::printf(" %10.4f", points(Eigen::Index(i), k));
      std::printf("\n");
    }
  });
}

void register_magnitude(CLI::App& group) {
  struct Options {
    std::string data, subject = "subject", first = "a", second = "b", rating = "rating", modulus_a, modulus_b, output;
    double modulus_value = 0;  // 0: from the table's modulus_value column, else 10
    int dims = 2, starts = 3;
    std::uint64_t seed = 1;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "magnitude",
      "Magnitude estimation of dissimilarity: per-listener modulus normalisation, geometric means per pair, "
      "dissimilarity matrix and metric SMACOF map");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Ratings CSV, one row per rated pair")->required();
  cmd->add_option("--subject", opt->subject, "Listener column")->capture_default_str();
  cmd->add_option("--a", opt->first, "First token column")->capture_default_str();
  cmd->add_option("--b", opt->second, "Second token column")->capture_default_str();
  cmd->add_option("--rating", opt->rating, "Magnitude estimate column (> 0)")->capture_default_str();
  cmd->add_option("--modulus-a", opt->modulus_a,
                  "Modulus pair, first token: each listener's ratings are scaled so this pair is rated "
                  "--modulus-value (default: the table's modulus_a/modulus_b columns, as the export writes them; "
                  "without a modulus pair: each listener scaled to the grand geometric mean)");
  cmd->add_option("--modulus-b", opt->modulus_b, "Modulus pair, second token");
  cmd->add_option("--modulus-value", opt->modulus_value,
                  "The number the modulus pair stands for (default: the table's modulus_value column, which the "
                  "export takes from the protocol; else 10)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--dims", opt->dims, "Dimensions of the map")->check(CLI::Range(1, 10))->capture_default_str();
  cmd->add_option("--starts", opt->starts, "SMACOF random starts besides the classical one")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_option("--seed", opt->seed, "Seed of the random starts")->capture_default_str();
  cmd->add_option("-o,--output", opt->output, "Write the dissimilarity matrix as square CSV (input of `stats mds`)");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    if (opt->modulus_a.empty() != opt->modulus_b.empty())
      throw InputError(SourceLocation{}, "--modulus-a and --modulus-b go together: give both tokens of the modulus pair");
    const TidyCsv table = read_stats_table(opt->data, *in);
    // The export's modulus columns (from the protocol): one pair and one value for all rows used.
    auto constant_column = [&](const std::string& name) -> std::optional<std::string> {
      if (!table.has_column(name) || table.rows() == 0) return std::nullopt;
      const std::size_t c = table.column(name);
      for (std::size_t r = 1; r < table.rows(); ++r)
        if (table.cell(r, c) != table.cell(0, c))
          throw InputError(table.where(r, c), "column '" + name + "': '" + table.cell(r, c) + "' here but '" +
                                                  table.cell(0, c) + "' on line " + std::to_string(table.where(0, c).line) +
                                                  ": rows from blocks with different moduli (choose one with --where block=ID)");
      return table.cell(0, c);
    };
    if (opt->modulus_a.empty()) {
      const auto a = constant_column("modulus_a"), b = constant_column("modulus_b");
      if (a && b && !a->empty() && !b->empty()) {
        opt->modulus_a = *a;
        opt->modulus_b = *b;
      }
    }
    MagnitudeOptions mo;
    if (!opt->modulus_a.empty()) mo.modulus = {opt->modulus_a, opt->modulus_b};
    if (opt->modulus_value > 0) {
      mo.modulus_value = opt->modulus_value;
    } else if (const auto v = constant_column("modulus_value"); v && !v->empty()) {
      mo.modulus_value = table.number(0, table.column("modulus_value"));
      if (!(mo.modulus_value > 0))
        throw InputError(table.where(0, table.column("modulus_value")), "column 'modulus_value': must be above 0");
    }
    const MagnitudeEstimation m =
        magnitude_estimation(table, {opt->subject, opt->first, opt->second, opt->rating}, mo);
    if (std::size_t(opt->dims) >= m.labels.size())
      throw InputError(SourceLocation{}, "--dims " + std::to_string(opt->dims) + ": need fewer dimensions than the " +
                                             std::to_string(m.labels.size()) + " tokens");
    SmacofOptions so;
    so.dims = opt->dims;
    so.random_starts = opt->starts;
    so.seed = opt->seed;
    const SmacofResult map = smacof(m.dissimilarity, so);
    if (!opt->output.empty()) {
      std::vector<std::string> header{"token"};
      header.insert(header.end(), m.labels.begin(), m.labels.end());
      std::string csv = csv::line(header);
      for (std::size_t i = 0; i < m.labels.size(); ++i) {
        std::vector<std::string> cells{m.labels[i]};
        for (std::size_t j = 0; j < m.labels.size(); ++j)
          cells.push_back(fmt("%.17g", m.dissimilarity(Eigen::Index(i), Eigen::Index(j))));
        csv += csv::line(cells);
      }
      write_file_atomically(opt->output, csv);
    }
    if (opt->json) {
      nlohmann::json listeners = nlohmann::json::array();
      for (const auto& l : m.listeners)
        listeners.push_back({{"subject", l.subject}, {"ratings", l.ratings}, {"factor", l.factor},
                             {"modulus_rating", num_json(l.modulus_rating)}, {"geometric_mean", l.geometric_mean}});
      nlohmann::json self = nlohmann::json::array();
      for (double v : m.self_ratings) self.push_back(num_json(v));
      nlohmann::json j = {{"labels", m.labels},
                          {"normalisation", m.modulus ? "modulus" : "geometric_mean"},
                          {"modulus", m.modulus ? nlohmann::json{opt->modulus_a, opt->modulus_b} : nlohmann::json(nullptr)},
                          {"modulus_value", mo.modulus_value},
                          {"grand_geometric_mean", m.grand_geometric_mean},
                          {"listeners", listeners},
                          {"self_ratings", self},
                          {"dissimilarity", matrix_json(m.dissimilarity)},
                          {"dims", opt->dims},
                          {"coords", matrix_json(map.points)},
                          {"stress1", map.stress1},
                          {"raw_stress", map.raw_stress},
                          {"starts", opt->starts + 1},
                          {"seed", opt->seed}};
      std::cout << j.dump() << "\n";
      return;
    }
    std::printf("magnitude estimation: %zu listeners, %zu tokens, normalised by %s\n", m.listeners.size(),
                m.labels.size(),
                m.modulus ? ("the modulus pair (" + opt->modulus_a + ", " + opt->modulus_b + ") = " +
                             fmt("%g", mo.modulus_value)).c_str()
                          : "each listener's geometric mean");
    for (const auto& l : m.listeners)
      std::printf("  %-16s %4zu ratings  factor %.4g\n", l.subject.c_str(), l.ratings, l.factor);
    std::printf("SMACOF map in %d dimensions: stress-1 = %.4f\n", opt->dims, map.stress1);
    for (std::size_t i = 0; i < m.labels.size(); ++i) {
      std::printf("%-20s", m.labels[i].c_str());
      for (int k = 0; k < opt->dims; ++k) std::printf(" %10.4f", map.points(Eigen::Index(i), k));
      std::printf("\n");
    }
  });
}

}  // namespace

// modalstudy stats limits: descending method of limits (the 2002 study's a_v procedure) per track.
void register_limits(CLI::App& group) {
  struct Options {
    std::string data, level, response, different = "different";
    std::vector<std::string> track;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "limits", "Descending method of limits: the smallest level at which no change was heard, per track");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per trial, in presentation order")->required();
  cmd->add_option("--level", opt->level, "Column of the level presented (falling, e.g. a_v in dB)")->required();
  cmd->add_option("--response", opt->response, "Column of the answer")->required();
  cmd->add_option("--different", opt->different, "Answer meaning 'heard a difference'")->capture_default_str();
  cmd->add_option("--track", opt->track, "Column(s) identifying a series (e.g. participant,object)")->delimiter(',');
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    const TidyCsv table = read_stats_table(opt->data, *in);
    const std::size_t cl = table.column(opt->level), cr = table.column(opt->response);
    if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
    nlohmann::json tracks = nlohmann::json::array();
    std::vector<double> thresholds;
    for (const auto& [name, rows] : group_rows(table, opt->track)) {
      std::vector<double> levels;
      std::vector<bool> different;
      for (std::size_t i = 0; i < rows.size(); ++i) {
        levels.push_back(table.number(rows[i], cl));
        if (i > 0 && !(levels[i] < levels[i - 1]))
          throw InputError(table.where(rows[i], cl), "column '" + opt->level + "': level " + table.cell(rows[i], cl) +
                                                         " does not fall below the previous trial of its series");
        different.push_back(table.cell(rows[i], cr) == opt->different);
      }
      const LimitsThreshold t = descending_limits_threshold(levels, different);
      if (t.threshold && !t.censored) thresholds.push_back(*t.threshold);
      tracks.push_back({{"track", name}, {"trials", levels.size()}, {"threshold", opt_json(t.threshold)},
                        {"censored", t.censored},
                        {"first_different_trial", t.first_different ? nlohmann::json(*t.first_different) : nlohmann::json()}});
    }
    nlohmann::json median = nullptr;
    if (!thresholds.empty()) median = quantile(thresholds, 0.5);
    if (opt->json) {
      std::cout << nlohmann::json{{"tracks", tracks}, {"median", median}}.dump() << "\n";
      return;
    }
    std::printf("%-24s %7s %10s\n", "Track", "trials", "threshold");
    for (const auto& t : tracks) {
      const std::string th = t["threshold"].is_null() ? "above start"
                             : fmt("%g", t["threshold"].get<double>()) + (t["censored"].get<bool>() ? " (censored)" : "");
      std::printf("%-24s %7zu %10s\n", t["track"].get<std::string>().c_str(), t["trials"].get<std::size_t>(), th.c_str());
    }
    if (!median.is_null()) std::printf("median threshold (uncensored series): %g\n", median.get<double>());
  });
}

void register_stats(CLI::App& app) {
  CLI::App* group = app.add_subcommand("stats", "Statistics of perceptual studies from tidy CSV files");
  group->require_subcommand(1);
  register_anova(*group);
  register_ttest(*group);
  register_confusion(*group);
  register_mushra(*group);
  register_ab(*group);
  register_staircase(*group);
  register_limits(*group);
  register_mds(*group);
  register_magnitude(*group);
}

}  // namespace ms::cli
