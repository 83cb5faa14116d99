// tidy_tables: one parser of each response format (response_format.hpp) into long rows.
#include "studyapp/core/tidy_tables.hpp"

#include <nlohmann/json.hpp>

#include "synthesis/csv.hpp"

namespace ms {

namespace {

std::string cell(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_null()) return "NA";
  return v.dump();
}

}  // namespace

std::string exported_participant(const std::string& code, std::int64_t id, bool export_personal) {
  // Codes are often names or initials: opaque ids unless the study allows personal fields.
  return export_personal ? code : "p" + std::to_string(id);
}

std::map<std::string, std::string> tidy_tables(const std::vector<ResponseRow>& rows) {
  const std::vector<std::string> key{"study", "participant", "session", "block", "trial"};
  const std::map<std::string, std::vector<std::string>> columns{
      {"ab", {"stimulus_a", "stimulus_b", "stimulus_x", "response", "correct"}},
      {"mushra", {"condition", "rating"}},
      {"magnitude", {"first", "second", "value"}},
      {"identify", {"stimulus", "response", "correct"}},
      {"rating", {"stimulus", "attribute", "value"}},
      {"adjust", {"stimulus", "key", "value", "plays", "rt_ms"}},
      {"staircase", {"stimulus", "parameter", "step", "level", "correct", "threshold"}},
      {"questionnaire", {"question", "answer"}}};
  std::map<std::string, std::string> out;
  for (const ResponseRow& r : rows) {
    const auto cols = columns.find(r.block_type);
    if (cols == columns.end()) continue;  // instructions
    std::string& csv = out[r.block_type + ".csv"];
    if (csv.empty()) {
      std::vector<std::string> header = key;
      header.insert(header.end(), cols->second.begin(), cols->second.end());
      csv = csv::line(header);
    }
    const std::vector<std::string> k{r.study, exported_participant(r.participant_code, r.participant, r.export_personal),
                                     std::to_string(r.session), r.block_id, std::to_string(r.trial_index)};
    auto add = [&](const std::vector<std::string>& rest) {
      std::vector<std::string> line = k;
      line.insert(line.end(), rest.begin(), rest.end());
      csv += csv::line(line);
    };
    const auto s = nlohmann::json::parse(r.stimuli_json);
    const auto v = nlohmann::json::parse(r.value_json);
    const auto at = [&](std::size_t i) { return i < s.size() ? s[i].get<std::string>() : std::string(); };
    if (r.block_type == "ab") {
      // ABX stores A, B, X: the answer is correct when the chosen one is X.
      std::string correct = "NA";
      if (s.size() == 3 && v.is_string()) correct = ((v == "A" ? at(0) : at(1)) == at(2)) ? "1" : "0";
      add({at(0), at(1), at(2), cell(v), correct});
    } else if (r.block_type == "mushra") {
      // The hidden reference is rated under its own name (`stats mushra --reference NAME`).
      for (const auto& [name, score] : v.items()) add({name, cell(score)});
    } else if (r.block_type == "magnitude") {
      add({at(0), at(1), cell(v)});
    } else if (r.block_type == "identify") {
      add({at(0), cell(v), at(0) == cell(v) ? "1" : "0"});
    } else if (r.block_type == "rating") {
      for (const auto& [attr, value] : v.items()) add({at(0), attr, cell(value)});
    } else if (r.block_type == "adjust") {
      for (const auto& [k2, value] : v.items())
        add({at(0), k2, cell(value), std::to_string(r.plays), nlohmann::json(r.rt_ms).dump()});
    } else if (r.block_type == "staircase") {
      const auto& levels = v.at("levels");
      const auto& correct = v.at("correct");
      for (std::size_t i = 0; i < levels.size(); ++i)
        add({at(0), v.value("parameter", ""), std::to_string(i), cell(levels[i]), cell(correct[i]), cell(v.at("threshold"))});
    } else if (r.block_type == "questionnaire") {
      for (const auto& [q, answer] : v.items()) add({q, cell(answer)});
    }
  }
  return out;
}

}  // namespace ms
