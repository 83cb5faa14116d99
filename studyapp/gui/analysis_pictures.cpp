// draw_analysis_pictures: responses -> analysis (confusion_from_pairs, mushra describe) -> plots.
#include "studyapp/gui/analysis_pictures.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "analysis/confusion.hpp"
#include "analysis/mushra.hpp"
#include "studyapp/plots/plots.hpp"

namespace ms::gui {

namespace {

struct BlockRows {
  std::string type;
  std::vector<const ResponseRow*> rows;
};

Picture confusion_picture(const std::string& block_id, const BlockRows& b, const std::string& out_dir) {
  std::vector<std::string> truth, response;
  std::set<std::string> all;
  for (const ResponseRow* r : b.rows) {
    const auto stimuli = nlohmann::json::parse(r->stimuli_json);
    const auto value = nlohmann::json::parse(r->value_json);
    if (!stimuli.is_array() || stimuli.empty() || !value.is_string()) continue;
    truth.push_back(stimuli[0].get<std::string>());
    response.push_back(value.get<std::string>());
    all.insert(truth.back());
    all.insert(response.back());
  }
  const std::vector<std::string> labels(all.begin(), all.end());
  const Eigen::MatrixXd pct = row_percent(confusion_from_pairs(labels, truth, response).counts);
  std::vector<std::vector<double>> matrix(labels.size(), std::vector<double>(labels.size()));
  for (std::size_t i = 0; i < labels.size(); ++i)
    for (std::size_t j = 0; j < labels.size(); ++j) matrix[i][j] = pct(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  plots::PlotOptions o;
  o.width_px = 640;
  o.height_px = 520;
  o.title = block_id + ": identification (row %)";
  o.x_label = "response";
  o.y_label = "stimulus";
  const std::string path = out_dir + "/" + block_id + "-confusion.png";
  plots::confusion_heatmap(path, labels, matrix, o);
  return {o.title, path};
}

Picture mushra_picture(const std::string& block_id, const BlockRows& b, const std::string& out_dir) {
  std::map<std::string, std::vector<double>> by_condition;
  for (const ResponseRow* r : b.rows) {
    const auto value = nlohmann::json::parse(r->value_json);
    if (!value.is_object()) continue;
    for (const auto& [name, score] : value.items())
      if (score.is_number()) by_condition[name].push_back(score.get<double>());
  }
  std::vector<std::string> names;
  std::vector<std::vector<double>> ratings;
  std::vector<double> means, lows, highs;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [name, values] : by_condition) {
    const MushraStat s = describe(name, values, 0.95);
    names.push_back(name);
    ratings.push_back(values);
    means.push_back(s.mean);
    lows.push_back(s.ci_low.value_or(nan));
    highs.push_back(s.ci_high.value_or(nan));
  }
  plots::PlotOptions o;
  o.width_px = 640;
  o.height_px = 480;
  o.title = block_id + ": MUSHRA ratings";
  const std::string path = out_dir + "/" + block_id + "-mushra.png";
  plots::mushra_boxplot(path, names, ratings, means, lows, highs, o);
  return {o.title, path};
}

}  // namespace

std::vector<Picture> draw_analysis_pictures(const std::vector<ResponseRow>& rows, const std::string& out_dir) {
  std::vector<std::string> order;
  std::map<std::string, BlockRows> blocks;
  for (const ResponseRow& r : rows) {
    if (r.block_type != "identify" && r.block_type != "mushra") continue;
    if (!blocks.count(r.block_id)) order.push_back(r.block_id);
    blocks[r.block_id].type = r.block_type;
    blocks[r.block_id].rows.push_back(&r);
  }
  std::vector<Picture> pictures;
  for (const std::string& id : order) {
    const BlockRows& b = blocks[id];
    pictures.push_back(b.type == "identify" ? confusion_picture(id, b, out_dir) : mushra_picture(id, b, out_dir));
  }
  return pictures;
}

}  // namespace ms::gui
