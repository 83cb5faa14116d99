// modalstudy stats mushra: BS.1534-3 post-screening, means and CIs per condition and item
// (analysis/mushra.hpp); --plot draws the boxes of ms::mushra_boxes, the experimenter view's picture.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "analysis/stats/mushra.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "studyapp/core/mushra_boxes.hpp"
#include "studyapp/plots/plots.hpp"

namespace ms::cli {

namespace {

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

std::size_t intervals_past_scale(const MushraResult& res) {
  std::size_t past = 0;
  for (const auto& c : res.conditions) past += c.ci_past_scale;
  for (const auto& it : res.items)
    for (const auto& c : it.conditions) past += c.ci_past_scale;
  return past;
}

std::vector<std::string> mushra_notices(const MushraResult& res) {
  std::vector<std::string> notices;
  if (res.averaged)
    notices.push_back(std::to_string(res.averaged) +
                      " assessor/item/condition cells were rated more than once; their ratings are averaged");
  if (res.included == 0) notices.push_back("every assessor was excluded by post-screening; no statistics");
  if (const std::size_t past = intervals_past_scale(res))
    notices.push_back(std::to_string(past) + " confidence interval(s) pass the 0-100 scale; reported as computed "
                      "(t interval, not clipped) and marked *");
  return notices;
}

nlohmann::json assessor_json(const MushraAssessor& a) {
  auto fraction = [](std::size_t k, std::size_t n) { return n ? nlohmann::json(double(k) / double(n)) : nullptr; };
  nlohmann::json checks = nlohmann::json::array();
  for (const auto& k : a.anchors)
    checks.push_back({{"anchor", k.anchor}, {"items", k.items}, {"above", k.above},
                      {"fraction", fraction(k.above, k.items)}, {"fails", k.fails}});
  return {{"subject", a.subject}, {"reference_items", a.reference_items}, {"reference_below", a.reference_below},
          {"reference_fraction", fraction(a.reference_below, a.reference_items)},
          {"reference_fails", a.reference_fails}, {"anchor_checks", checks}, {"anchor_fails", a.anchor_fails},
          {"excluded", a.excluded}};
}

nlohmann::json mushra_json(const MushraResult& res, const MushraOptions& o, const std::vector<std::string>& notices) {
  nlohmann::json assessors = nlohmann::json::array(), conds = nlohmann::json::array(), items = nlohmann::json::array();
  for (const auto& a : res.assessors) assessors.push_back(assessor_json(a));
  for (const auto& c : res.conditions) conds.push_back(stat_json(c));
  for (const auto& it : res.items) {
    nlohmann::json ic = nlohmann::json::array();
    for (const auto& c : it.conditions) ic.push_back(stat_json(c));
    items.push_back({{"item", it.item}, {"conditions", ic}});
  }
  return {{"reference", o.reference}, {"anchors", o.anchors}, {"n_assessors", res.assessors.size()},
          {"n_included", res.included}, {"conf_level", o.conf_level}, {"assessors", assessors},
          {"conditions", conds}, {"items", items}, {"notices", notices}};
}

void print_mushra(const MushraResult& res) {
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
  if (intervals_past_scale(res)) std::printf("* the interval passes the 0-100 scale (reported as computed, not clipped)\n");
}

void draw_boxes(const std::string& path, const std::string& data, const MushraTable& t) {
  const MushraBoxes boxes = mushra_boxes(t.ratings, t.options);
  plots::PlotOptions po;
  po.title = "MUSHRA: " + data + " (" + std::to_string(boxes.kept) + " assessors kept)";
  po.x_label = "Condition";
  po.y_label = "Rating (0-100)";
  plots::mushra_boxplot(path, boxes.conditions, boxes.ratings, boxes.means, boxes.ci_low, boxes.ci_high, po);
}

}  // namespace

void register_stats_mushra(CLI::App& group) {
  struct Options {
    std::string data, plot;
    MushraColumns columns;
    MushraOptions m;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "mushra", "MUSHRA (ITU-R BS.1534-3): post-screening of assessors, means and 95% CIs per condition and item");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Tidy CSV, one row per rating (webMUSHRA column names accepted)")->required();
  cmd->add_option("--subject", opt->columns.subject, "Assessor column (default: participant, subject or session_uuid)");
  cmd->add_option("--item", opt->columns.item, "Item column (default: trial, item or trial_id)");
  cmd->add_option("--condition", opt->columns.condition, "Condition column (default: condition or rating_stimulus)");
  cmd->add_option("--rating", opt->columns.rating, "Rating column, 0-100 (default: rating or rating_score)");
  cmd->add_option("--reference", opt->m.reference, "Name of the hidden-reference condition")->capture_default_str();
  cmd->add_option("--anchor", opt->m.anchors, "Anchor condition(s) to check (default: conditions named anchor*)");
  cmd->add_flag("--screen-anchors", opt->m.screen_anchors,
                "Also exclude assessors rating an anchor above 90 in more than 15% of items");
  cmd->add_option("--conf-level", opt->m.conf_level, "Confidence level")->check(CLI::Range(0.5, 0.9999));
  cmd->add_option("--plot", opt->plot, "Also draw box plots with means and CIs: FILE.png or FILE.svg");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    if (!opt->plot.empty()) plots::check_output_path(opt->plot);
    const MushraTable t = mushra_from_table(read_stats_table(opt->data, *in), opt->columns, opt->m);
    const MushraResult res = mushra_analyse(t.ratings, t.options);
    if (!opt->plot.empty()) draw_boxes(opt->plot, opt->data, t);
    const std::vector<std::string> notices = mushra_notices(res);
    print_notices(notices, opt->data);
    if (opt->json) std::cout << mushra_json(res, t.options, notices).dump() << "\n";
    else print_mushra(res);
  });
}

}  // namespace ms::cli
