// draw_analysis_pictures: responses -> analysis (confusion_from_pairs, mushra_boxes, ab_proportions,
// magnitude_map) -> plots.
#include "studyapp/gui/analysis_pictures.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "analysis/stats/confusion.hpp"
#include "analysis/stats/mushra.hpp"
#include "studyapp/core/answers.hpp"
#include "studyapp/core/block_summaries.hpp"
#include "studyapp/core/mushra_boxes.hpp"
#include "studyapp/plots/plots.hpp"

namespace ms::gui {

namespace {

std::string svg_of(const std::string& png) { return png.substr(0, png.size() - 4) + ".svg"; }

// A row's stored answer as its block type's typed answer (the store only holds checked answers).
template <class T>
T stored_answer(const ResponseRow& r) {
  return std::get<T>(read_stored_answer(r.block_type, nlohmann::json::parse(r.value_json)));
}

struct BlockRows {
  std::string type;
  std::vector<const ResponseRow*> rows;
};

Picture confusion_picture(const std::string& block_id, const BlockRows& b, const std::string& out_dir) {
  std::vector<std::string> truth, response;
  std::set<std::string> all;
  for (const ResponseRow* r : b.rows) {
    const auto stimuli = nlohmann::json::parse(r->stimuli_json);
    if (!stimuli.is_array() || stimuli.empty()) continue;
    truth.push_back(stimuli[0].get<std::string>());
    response.push_back(stored_answer<IdentifyAnswer>(*r).label);
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
  plots::confusion_heatmap(svg_of(path), labels, matrix, o);
  return {o.title, path, svg_of(path)};
}

// The same recipe as `modalstudy stats mushra --plot`: boxes of the assessors post-screening keeps (the
// hidden reference named by the block's automatic anchors; without them every assessor is kept).
Picture mushra_picture(const std::string& block_id, const BlockRows& b, const std::string& out_dir) {
  std::vector<MushraRating> ratings;
  std::vector<std::string> conditions;
  for (const ResponseRow* r : b.rows) {
    for (const auto& [name, score] : stored_answer<MushraAnswer>(*r).scores) {
      ratings.push_back({r->participant_code + "#" + std::to_string(r->session), std::to_string(r->trial_index), name,
                         score});
      conditions.push_back(name);
    }
  }
  MushraOptions options;
  options.reference = reference_from_anchor_names(conditions);
  if (options.reference.empty()) options.reference_min = 0.0;  // no hidden reference known: keep everyone
  const MushraBoxes boxes = mushra_boxes(ratings, options);
  plots::PlotOptions o;
  o.width_px = 640;
  o.height_px = 480;
  o.title = block_id + ": MUSHRA ratings (" + std::to_string(boxes.kept) + " of " + std::to_string(boxes.assessors) +
            " assessors kept by post-screening)";
  o.x_label = "Condition";
  o.y_label = "Rating (0-100)";
  const std::string path = out_dir + "/" + block_id + "-mushra.png";
  for (const std::string& p : {path, svg_of(path)})
    plots::mushra_boxplot(p, boxes.conditions, boxes.ratings, boxes.means, boxes.ci_low, boxes.ci_high, o);
  return {o.title, path, svg_of(path)};
}

// Every session's track: the presented level per step.
Picture staircase_picture(const std::string& block_id, const BlockRows& b, const std::string& out_dir) {
  std::vector<plots::Series> tracks;
  for (const ResponseRow* r : b.rows) {
    const StaircaseAnswer track = stored_answer<StaircaseAnswer>(*r);
    plots::Series s;
    s.name = r->participant_code + (r->autopilot ? " (simulated)" : "");
    for (std::size_t i = 0; i < track.levels.size(); ++i) s.points.push_back({static_cast<double>(i + 1), track.levels[i]});
    tracks.push_back(std::move(s));
  }
  plots::PlotOptions o;
  o.width_px = 640;
  o.height_px = 420;
  o.title = block_id + ": staircase tracks";
  o.x_label = "Step";
  o.y_label = "Level";
  const std::string path = out_dir + "/" + block_id + "-staircase.png";
  plots::line_plot(path, tracks, o);
  plots::line_plot(svg_of(path), tracks, o);
  return {o.title, path, svg_of(path)};
}

// Each pair's proportion as a mean with its interval on the 0-100 axis (no boxes: one number per pair).
Picture ab_picture(const std::string& block_id, const std::vector<ResponseRow>& rows, const std::string& out_dir) {
  std::vector<std::string> pairs;
  std::vector<std::vector<double>> none;
  std::vector<double> pct, low, high;
  std::set<std::string> measures;
  for (const AbProportion& p : ab_proportions(rows, block_id)) {
    pairs.push_back(p.first + " / " + p.second + " (n=" + std::to_string(static_cast<unsigned>(p.test.trials)) + ")");
    none.emplace_back();
    pct.push_back(100 * p.test.proportion);
    low.push_back(100 * p.test.ci_low);
    high.push_back(100 * p.test.ci_high);
    measures.insert(p.measure.rfind("chose", 0) == 0 ? "preferred" : p.measure);
  }
  std::string measure;
  for (const std::string& m : measures) measure += (measure.empty() ? "" : " / ") + m;
  plots::PlotOptions o;
  o.width_px = 720;  // room for the legend line under the axis
  o.height_px = 420;
  o.title = block_id + ": proportion " + measure + " per pair (95 % Clopper-Pearson intervals)";
  o.x_label = "Pair";
  o.y_label = "Proportion " + measure + " (%)";
  const std::string path = out_dir + "/" + block_id + "-ab.png";
  for (const std::string& p : {path, svg_of(path)}) plots::mushra_boxplot(p, pairs, none, pct, low, high, o);
  return {o.title, path, svg_of(path)};
}

// The perceptual map of the block's dissimilarities; a block whose design cannot be mapped says why.
Picture magnitude_picture(const std::string& block_id, const std::vector<ResponseRow>& rows, const Protocol* protocol,
                          const std::string& out_dir) {
  const MagnitudeMap m = magnitude_map(rows, block_id, protocol);
  std::vector<plots::XY> points;
  for (std::size_t i = 0; i < m.labels.size(); ++i) points.push_back({m.x[i], m.y[i]});
  plots::PlotOptions o;
  o.width_px = 560;
  o.height_px = 480;
  o.title = m.problem.empty() ? block_id + ": magnitude estimates, classical MDS map (" + std::to_string(m.listeners) +
                                    " listener" + (m.listeners == 1 ? "" : "s") + ")"
                              : block_id + ": no MDS map (" + m.problem + ")";
  o.x_label = "Dimension 1";
  o.y_label = "Dimension 2";
  const std::string path = out_dir + "/" + block_id + "-magnitude.png";
  for (const std::string& p : {path, svg_of(path)}) plots::mds_map(p, points, m.labels, o);
  return {o.title, path, svg_of(path)};
}

}  // namespace

std::vector<Picture> draw_analysis_pictures(const std::vector<ResponseRow>& rows, const std::string& out_dir,
                                            const std::map<std::string, Protocol>& protocols) {
  static const std::set<std::string> drawn{"identify", "mushra", "staircase", "magnitude", "ab"};
  std::vector<std::string> order;
  std::map<std::string, BlockRows> blocks;
  std::map<std::string, std::string> study_of;
  for (const ResponseRow& r : rows) {
    if (!drawn.count(r.block_type)) continue;
    if (!blocks.count(r.block_id)) order.push_back(r.block_id);
    blocks[r.block_id].type = r.block_type;
    blocks[r.block_id].rows.push_back(&r);
    study_of[r.block_id] = r.study;
  }
  std::vector<Picture> pictures;
  for (const std::string& id : order) {
    const BlockRows& b = blocks[id];
    const auto protocol = protocols.find(study_of[id]);
    if (b.type == "identify") pictures.push_back(confusion_picture(id, b, out_dir));
    else if (b.type == "mushra") pictures.push_back(mushra_picture(id, b, out_dir));
    else if (b.type == "staircase") pictures.push_back(staircase_picture(id, b, out_dir));
    else if (b.type == "ab") pictures.push_back(ab_picture(id, rows, out_dir));
    else pictures.push_back(magnitude_picture(id, rows, protocol == protocols.end() ? nullptr : &protocol->second, out_dir));
  }
  return pictures;
}

}  // namespace ms::gui
