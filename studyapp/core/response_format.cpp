// check_answer: the response formats of response_format.hpp, enforced before anything is stored.
#include "studyapp/core/response_format.hpp"

#include <algorithm>
#include <cmath>

namespace ms {

namespace {

bool is_number(const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

std::string one_of(const nlohmann::json& v, const std::vector<std::string>& options) {
  if (v.is_string() && std::find(options.begin(), options.end(), v.get<std::string>()) != options.end()) return "";
  std::string list;
  for (const auto& o : options) list += (list.empty() ? "" : ", ") + o;
  return "expected one of " + list + ", got " + v.dump();
}

// An object with exactly the given keys, each value checked by `ok`.
template <class Ok>
std::string object_of(const nlohmann::json& v, const std::vector<std::string>& keys, Ok ok, const std::string& what) {
  if (!v.is_object()) return "expected an object {key: " + what + "}, got " + v.dump();
  for (const auto& k : keys) {
    if (!v.contains(k)) return "missing '" + k + "'";
    if (!ok(k, v[k])) return "'" + k + "' must be " + what + ", got " + v[k].dump();
  }
  for (const auto& [k, _] : v.items())
    if (std::find(keys.begin(), keys.end(), k) == keys.end()) return "unexpected key '" + k + "'";
  return "";
}

}  // namespace

std::string question_id(const Question& q, std::size_t index) {
  return q.id.empty() ? "q" + std::to_string(index + 1) : q.id;
}

std::string check_answer(const Block& block, const Trial& trial, const nlohmann::json& v) {
  switch (block.type) {
    case BlockType::instructions:
      return v == "ok" ? "" : "instructions are answered with \"ok\"";
    case BlockType::ab: {
      const auto& ab = std::get<AbBlock>(block.body);
      if (ab.mode == AbMode::same_different) return one_of(v, {"same", "different"});
      if (ab.mode == AbMode::bipolar) {
        if (v.is_number_integer() && v.get<int>() >= -3 && v.get<int>() <= 3) return "";
        return "expected an integer from -3 to 3, got " + v.dump();
      }
      return one_of(v, {"A", "B"});
    }
    case BlockType::mushra:
      return object_of(v, trial.stimuli, [](const std::string&, const nlohmann::json& x) {
        return is_number(x) && x.get<double>() >= 0.0 && x.get<double>() <= 100.0;
      }, "a score from 0 to 100");
    case BlockType::magnitude: {
      const bool zero_allowed = std::get<MagnitudeBlock>(block.body).identical_pairs;  // "no difference"
      if (is_number(v) && (v.get<double>() > 0.0 || (zero_allowed && v.get<double>() == 0.0))) return "";
      return (zero_allowed ? "expected a number >= 0, got " : "expected a positive number, got ") + v.dump();
    }
    case BlockType::identify:
      return one_of(v, std::get<IdentifyBlock>(block.body).labels);
    case BlockType::rating: {
      const auto& r = std::get<RatingBlock>(block.body);
      std::vector<std::string> keys;
      for (const auto& a : r.attributes) keys.push_back(a.name);
      return object_of(v, keys, [&](const std::string& k, const nlohmann::json& x) {
        const auto a = std::find_if(r.attributes.begin(), r.attributes.end(), [&](const auto& y) { return y.name == k; });
        return x.is_number_integer() && x.get<int>() >= 1 && x.get<int>() <= a->points;
      }, "an integer from 1 to the attribute's points");
    }
    case BlockType::adjust: {
      const auto& a = std::get<AdjustBlock>(block.body);
      std::vector<std::string> keys;
      for (const auto& s : a.sliders) keys.push_back(s.key);
      return object_of(v, keys, [&](const std::string& k, const nlohmann::json& x) {
        const auto s = std::find_if(a.sliders.begin(), a.sliders.end(), [&](const auto& y) { return y.key == k; });
        const double lo = std::min(s->min, s->max), hi = std::max(s->min, s->max);
        return is_number(x) && x.get<double>() >= lo - 1e-9 * std::abs(hi - lo) &&
               x.get<double>() <= hi + 1e-9 * std::abs(hi - lo);
      }, "a value within the slider's range");
    }
    case BlockType::staircase:
      if (v.is_object() && v.contains("levels") && v["levels"].is_array() && v.contains("correct") &&
          v["correct"].is_array() && v["levels"].size() == v["correct"].size() && v.contains("threshold") &&
          (v["threshold"].is_null() || is_number(v["threshold"])))
        return "";
      return "expected {\"levels\":[...],\"correct\":[...],\"threshold\":...}";
    case BlockType::questionnaire: {
      const auto& q = std::get<QuestionnaireBlock>(block.body);
      std::vector<std::string> keys;
      for (std::size_t i = 0; i < q.questions.size(); ++i) keys.push_back(question_id(q.questions[i], i));
      return object_of(v, keys, [&](const std::string& k, const nlohmann::json& x) {
        const auto i = std::size_t(std::find(keys.begin(), keys.end(), k) - keys.begin());
        const auto& opts = q.questions[i].options;
        return x.is_string() && (opts.empty() || std::find(opts.begin(), opts.end(), x.get<std::string>()) != opts.end());
      }, "text (or one of the question's options)");
    }
    case BlockType::unknown:
      break;
  }
  return "block '" + block.id + "' has an unknown type";
}

std::string ab_chosen_stimulus(const nlohmann::json& stimuli, const std::string& answer) {
  return stimuli.at(answer == "A" ? 0 : 1).get<std::string>();
}

bool abx_correct(const nlohmann::json& stimuli, const std::string& answer) {
  return ab_chosen_stimulus(stimuli, answer) == stimuli.at(2).get<std::string>();
}

}  // namespace ms
