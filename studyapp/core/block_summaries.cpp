// ab_proportions, magnitude_map: stored responses -> binomial_test / magnitude_estimation + classical_mds.
#include "studyapp/core/block_summaries.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>

#include "analysis/stats/magnitude_estimation.hpp"
#include "analysis/stats/mds.hpp"
#include "synthesis/tidy_csv.hpp"
#include "studyapp/core/answers.hpp"
#include "studyapp/core/response_format.hpp"
#include "studyapp/core/tidy_tables.hpp"

namespace ms {

std::vector<AbProportion> ab_proportions(const std::vector<ResponseRow>& rows, const std::string& block_id) {
  struct Count {
    std::string first, second, measure;
    unsigned successes = 0, trials = 0;
  };
  std::vector<Count> counts;
  for (const ResponseRow& r : rows) {
    if (r.block_id != block_id || r.block_type != "ab") continue;
    const auto s = nlohmann::json::parse(r.stimuli_json);
    if (!s.is_array() || s.size() < 2) continue;
    const Answer answer = read_stored_answer("ab", nlohmann::json::parse(r.value_json));
    const auto* same_different = std::get_if<SameDifferentAnswer>(&answer);
    const auto* choice = std::get_if<ChoiceAnswer>(&answer);
    if (!same_different && !choice) continue;  // bipolar scores have no proportion
    const std::string a = s[0].get<std::string>(), b = s[1].get<std::string>();
    auto it = std::find_if(counts.begin(), counts.end(), [&](const Count& c) {
      return (c.first == a && c.second == b) || (c.first == b && c.second == a);
    });
    if (it == counts.end()) {
      Count c{a, b, "", 0, 0};
      c.measure = s.size() == 3 && choice ? "correct" : same_different ? "different" : "chose " + a;
      counts.push_back(c);
      it = counts.end() - 1;
    }
    bool success = false;
    if (it->measure == "correct") success = choice && abx_correct(s, choice->chosen);
    else if (it->measure == "different") success = same_different && same_different->different;
    else success = choice && ab_chosen_stimulus(s, choice->chosen) == it->first;
    it->successes += success ? 1u : 0u;
    ++it->trials;
  }
  std::vector<AbProportion> out;
  for (const Count& c : counts) out.push_back({c.first, c.second, c.measure, binomial_test(c.successes, c.trials)});
  return out;
}

MagnitudeMap magnitude_map(const std::vector<ResponseRow>& rows, const std::string& block_id, const Protocol* protocol) {
  MagnitudeMap map;
  std::vector<ResponseRow> mine;
  for (const ResponseRow& r : rows)
    if (r.block_id == block_id && r.block_type == "magnitude") mine.push_back(r);
  std::map<std::string, Protocol> protocols;
  if (protocol && !mine.empty()) protocols.emplace(mine.front().study, *protocol);
  const auto tables = tidy_tables(mine, protocols);
  const auto csv = tables.find("magnitude.csv");
  if (csv == tables.end()) {
    map.problem = "no magnitude responses";
    return map;
  }
  try {
    const TidyCsv all = TidyCsv::parse(csv->second, block_id);
    const std::size_t first = all.column("first"), second = all.column("second"), value = all.column("value");
    std::vector<std::size_t> keep;
    for (std::size_t i = 0; i < all.rows(); ++i)
      if (!(all.cell(i, first) == all.cell(i, second) && all.number(i, value) == 0.0)) keep.push_back(i);
    const TidyCsv table = all.keep_rows(keep);
    MagnitudeOptions options;
    const Block* block = nullptr;
    if (protocol)
      for (const Block& b : protocol->blocks)
        if (b.id == block_id) block = &b;
    if (const auto* mb = block ? std::get_if<MagnitudeBlock>(&block->body) : nullptr) {
      if (mb->modulus) options.modulus = std::make_pair((*mb->modulus)[0].name, (*mb->modulus)[1].name);
      options.modulus_value = mb->modulus_value;
    }
    const MagnitudeEstimation m = magnitude_estimation(table, {"participant", "first", "second", "value"}, options);
    const ClassicalMds mds = classical_mds(m.dissimilarity, 2);
    map.labels = m.labels;
    map.listeners = m.listeners.size();
    for (Eigen::Index i = 0; i < mds.points.rows(); ++i) {
      map.x.push_back(mds.points(i, 0));
      map.y.push_back(mds.points.cols() > 1 ? mds.points(i, 1) : 0.0);
    }
  } catch (const std::exception& e) {
    map.problem = e.what();
  }
  return map;
}

}  // namespace ms
