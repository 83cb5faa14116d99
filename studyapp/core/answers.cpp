// Answers: the stored JSON of each block type's answer, read by shape and checked against its trial.
#include "studyapp/core/answers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "analysis/stats/token_series.hpp"

namespace ms {

using nlohmann::json;

namespace {

bool is_finite_number(const json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

std::string list_of(const std::vector<std::string>& options) {
  std::string list;
  for (const auto& o : options) list += (list.empty() ? "" : ", ") + o;
  return list;
}

std::string one_of(const json& v, const std::vector<std::string>& options) {
  if (v.is_string() && std::find(options.begin(), options.end(), v.get<std::string>()) != options.end())
    return v.get<std::string>();
  throw AnswerError("expected one of " + list_of(options) + ", got " + v.dump());
}

// An object whose every value `read` converts (or rejects with nullopt), described as `what`.
template <class T, class Read>
std::map<std::string, T> object_of(const json& v, const std::string& what, Read read) {
  if (!v.is_object()) throw AnswerError("expected an object {key: " + what + "}, got " + v.dump());
  std::map<std::string, T> out;
  for (const auto& [k, x] : v.items()) {
    const std::optional<T> value = read(x);
    if (!value) throw AnswerError("'" + k + "' must be " + what + ", got " + x.dump());
    out.emplace(k, *value);
  }
  return out;
}

// The map has exactly `keys`, and ok(i, value) accepts the value of keys[i].
template <class T, class Ok>
void check_keys(const std::map<std::string, T>& m, const std::vector<std::string>& keys, Ok ok, const std::string& what) {
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const auto it = m.find(keys[i]);
    if (it == m.end()) throw AnswerError("missing '" + keys[i] + "'");
    if (!ok(i, it->second)) throw AnswerError("'" + keys[i] + "' must be " + what + ", got " + json(it->second).dump());
  }
  for (const auto& [k, _] : m)
    if (std::find(keys.begin(), keys.end(), k) == keys.end()) throw AnswerError("unexpected key '" + k + "'");
}

std::optional<double> finite(const json& x) { return is_finite_number(x) ? std::optional(x.get<double>()) : std::nullopt; }

AbInterval interval_from(const json& v) { return one_of(v, {"A", "B"}) == "A" ? AbInterval::a : AbInterval::b; }

template <class T>
T get_as(const json& v) {
  T a;
  from_json(v, a);
  return a;
}

}  // namespace

std::string to_string(AbInterval i) { return i == AbInterval::a ? "A" : "B"; }
AbInterval other(AbInterval i) { return i == AbInterval::a ? AbInterval::b : AbInterval::a; }

json mushra_score_json(double score) {
  if (score == std::floor(score) && std::abs(score) < 1e15) return json(static_cast<std::int64_t>(score));
  return json(score);
}

void to_json(json& j, const InstructionsAnswer&) { j = "ok"; }
void to_json(json& j, const SameDifferentAnswer& a) { j = a.different ? "different" : "same"; }
void to_json(json& j, const ChoiceAnswer& a) { j = to_string(a.chosen); }
void to_json(json& j, const BipolarAnswer& a) { j = a.score; }
void to_json(json& j, const MushraAnswer& a) {
  j = json::object();
  for (const auto& [name, score] : a.scores) j[name] = mushra_score_json(score);
}
void to_json(json& j, const MagnitudeAnswer& a) { j = a.value; }
void to_json(json& j, const IdentifyAnswer& a) { j = a.label; }
void to_json(json& j, const RatingAnswer& a) { j = a.points; }
void to_json(json& j, const AdjustAnswer& a) { j = a.values; }
void to_json(json& j, const StaircaseAnswer& a) {
  j = json{{"levels", a.levels}, {"correct", a.correct}, {"parameter", a.parameter}};
  if (!a.chosen.empty()) {
    j["chosen"] = json::array();
    for (AbInterval i : a.chosen) j["chosen"].push_back(to_string(i));
  }
  j["threshold"] = a.threshold ? json(*a.threshold) : json(nullptr);
}
void to_json(json& j, const QuestionnaireAnswer& a) { j = a.answers; }
void to_json(json& j, const Bs1116Answer& a) { j = a.grades; }
void to_json(json& j, const LimitsAnswer& a) {
  j = json{{"parameter", a.parameter}, {"levels", a.levels}, {"responses", json::array()}};
  for (bool d : a.different) j["responses"].push_back(d ? "different" : "same");
  j["threshold"] = a.threshold ? json(*a.threshold) : json(nullptr);
}
void to_json(json& j, const TokensAnswer& a) {
  TokenSeries series(a.from, a.to);
  j = json{{"from", a.from}, {"to", a.to}, {"responses", json::array()}};
  for (bool d : a.different) {
    j["responses"].push_back(d ? "different" : "same");
    series.record(d);
  }
  j["distinguished"] = series.distinguished();
}
void to_json(json& j, const ChangepointAnswer& a) { j = json{{"marks", a.marks}}; }
void to_json(json& j, const Answer& a) {
  std::visit([&](const auto& x) { to_json(j, x); }, a);
}

void from_json(const json& j, InstructionsAnswer&) {
  if (j != "ok") throw AnswerError("instructions are answered with \"ok\"");
}
void from_json(const json& j, SameDifferentAnswer& a) { a.different = one_of(j, {"same", "different"}) == "different"; }
void from_json(const json& j, ChoiceAnswer& a) { a.chosen = interval_from(j); }
void from_json(const json& j, BipolarAnswer& a) {
  if (!j.is_number_integer() || j.get<std::int64_t>() < -3 || j.get<std::int64_t>() > 3)
    throw AnswerError("expected an integer from -3 to 3, got " + j.dump());
  a.score = j.get<int>();
}
void from_json(const json& j, MushraAnswer& a) {
  a.scores = object_of<double>(j, "a score from 0 to 100", [](const json& x) {
    const auto v = finite(x);
    return v && *v >= 0.0 && *v <= 100.0 ? v : std::nullopt;
  });
}
void from_json(const json& j, Bs1116Answer& a) {
  a.grades = object_of<double>(j, "a grade from 1.0 to 5.0", [](const json& x) {
    const auto v = finite(x);
    return v && *v >= kBs1116GradeMin && *v <= kBs1116GradeMax ? v : std::nullopt;
  });
}
void from_json(const json& j, MagnitudeAnswer& a) {
  const auto v = finite(j);
  if (!v || *v < 0.0) throw AnswerError("expected a number >= 0, got " + j.dump());
  a.value = *v;
}
void from_json(const json& j, IdentifyAnswer& a) {
  if (!j.is_string()) throw AnswerError("expected a label, got " + j.dump());
  a.label = j.get<std::string>();
}
void from_json(const json& j, RatingAnswer& a) {
  a.points = object_of<int>(j, "an integer from 1 to the attribute's points", [](const json& x) {
    return x.is_number_integer() && x.get<std::int64_t>() >= 1 &&
                       x.get<std::int64_t>() <= std::numeric_limits<int>::max()
               ? std::optional(x.get<int>())
               : std::nullopt;
  });
}
void from_json(const json& j, AdjustAnswer& a) { a.values = object_of<double>(j, "a number", finite); }
void from_json(const json& j, StaircaseAnswer& a) {
  const auto bad = [] { return AnswerError("expected {\"levels\":[...],\"correct\":[...],\"threshold\":...}"); };
  if (!j.is_object() || !j.contains("levels") || !j["levels"].is_array() || !j.contains("correct") ||
      !j["correct"].is_array() || j["levels"].size() != j["correct"].size() || !j.contains("threshold") ||
      !(j["threshold"].is_null() || is_finite_number(j["threshold"])))
    throw bad();
  a = StaircaseAnswer{};
  if (j.contains("parameter")) {
    if (!j["parameter"].is_string()) throw bad();
    a.parameter = j["parameter"].get<std::string>();
  }
  for (const json& level : j["levels"]) {
    if (!is_finite_number(level)) throw AnswerError("a staircase level must be a number, got " + level.dump());
    a.levels.push_back(level.get<double>());
  }
  for (const json& c : j["correct"]) {  // true/false (early stores: 1/0)
    if (c.is_boolean()) a.correct.push_back(c.get<bool>());
    else if (c == 0 || c == 1) a.correct.push_back(c == 1);
    else throw AnswerError("a staircase step is correct true or false, got " + c.dump());
  }
  if (j.contains("chosen")) {
    if (!j["chosen"].is_array() || j["chosen"].size() != a.levels.size())
      throw AnswerError("a staircase's \"chosen\" holds one \"A\" or \"B\" per step");
    for (const json& c : j["chosen"]) a.chosen.push_back(interval_from(c));
  }
  if (!j["threshold"].is_null()) a.threshold = j["threshold"].get<double>();
}
void from_json(const json& j, LimitsAnswer& a) {
  if (!j.is_object() || !j.contains("levels") || !j["levels"].is_array() || !j.contains("responses") ||
      !j["responses"].is_array() || !j.contains("parameter") || !j["parameter"].is_string() ||
      !j.contains("threshold") || !(j["threshold"].is_null() || is_finite_number(j["threshold"])))
    throw AnswerError("expected {\"parameter\":key,\"levels\":[...],\"responses\":[...],\"threshold\":...}");
  if (j["levels"].size() != j["responses"].size())
    throw AnswerError("a series has one response per level: " + std::to_string(j["levels"].size()) + " levels, " +
                      std::to_string(j["responses"].size()) + " responses");
  a = LimitsAnswer{};
  a.parameter = j["parameter"].get<std::string>();
  for (const json& level : j["levels"]) {
    if (!is_finite_number(level)) throw AnswerError("a series level must be a number, got " + level.dump());
    if (!a.levels.empty() && !(level.get<double>() < a.levels.back()))
      throw AnswerError("a descending series' levels must fall, got " + level.dump() + " after " + json(a.levels.back()).dump());
    a.levels.push_back(level.get<double>());
  }
  for (const json& r : j["responses"]) a.different.push_back(one_of(r, {"same", "different"}) == "different");
  for (std::size_t i = 0; i + 1 < a.different.size(); ++i)
    if (a.different[i]) throw AnswerError("a series ends at its first \"different\" (trial " + std::to_string(i + 1) + ")");
  if (!j["threshold"].is_null()) a.threshold = j["threshold"].get<double>();
}
void from_json(const json& j, TokensAnswer& a) {
  const auto whole = [](const json& v) { return v.is_number_integer() && v.get<long long>() >= 1 && v.get<long long>() <= 100000; };
  if (!j.is_object() || j.size() != 4 || !j.contains("from") || !whole(j["from"]) || !j.contains("to") ||
      !whole(j["to"]) || !j.contains("responses") || !j["responses"].is_array() || !j.contains("distinguished") ||
      !j["distinguished"].is_array())
    throw AnswerError("expected {\"from\":K,\"to\":k,\"responses\":[...],\"distinguished\":[...]}");
  a = TokensAnswer{j["from"].get<int>(), j["to"].get<int>(), {}};
  if (!(a.from > a.to)) throw AnswerError("a token series runs from more modes to fewer: from " + j["from"].dump() + ", to " + j["to"].dump());
  for (const json& r : j["responses"]) a.different.push_back(one_of(r, {"same", "different"}) == "different");
  if (a.different.size() != std::size_t(a.from - a.to))
    throw AnswerError("a token series compares every token below the first once: " + std::to_string(a.from - a.to) +
                      " responses from " + j["from"].dump() + " to " + j["to"].dump() + ", got " +
                      std::to_string(a.different.size()));
  TokenSeries series(a.from, a.to);
  for (bool d : a.different) series.record(d);
  if (j["distinguished"] != json(series.distinguished()))
    throw AnswerError("\"distinguished\" must be the references the responses lead to, " +
                      json(series.distinguished()).dump() + ", got " + j["distinguished"].dump());
}
void from_json(const json& j, ChangepointAnswer& a) {
  if (!j.is_object() || j.size() != 1 || !j.contains("marks") || !j["marks"].is_array())
    throw AnswerError("expected {\"marks\":[position, ...]}, got " + j.dump());
  a = ChangepointAnswer{};
  for (const json& m : j["marks"]) {
    if (!m.is_number_integer() || m.get<long long>() < 0 || m.get<long long>() > 100000)
      throw AnswerError("a mark is a sound's position in the sweep (0, 1, ...), got " + m.dump());
    const auto at = std::size_t(m.get<long long>());
    if (at == 0) throw AnswerError("the first sound cannot be marked: there is nothing before it to change from");
    if (!a.marks.empty() && at <= a.marks.back())
      throw AnswerError("marks rise and are distinct, got " + m.dump() + " after " + std::to_string(a.marks.back()));
    a.marks.push_back(at);
  }
}
void from_json(const json& j, QuestionnaireAnswer& a) {
  a.answers = object_of<std::string>(j, "text (or one of the question's options)", [](const json& x) {
    return x.is_string() ? std::optional(x.get<std::string>()) : std::nullopt;
  });
}

std::string question_id(const Question& q, std::size_t index) {
  return q.id.empty() ? "q" + std::to_string(index + 1) : q.id;
}

Answer read_stored_answer(const std::string& block_type, const json& v) {
  if (block_type == "instructions") return get_as<InstructionsAnswer>(v);
  if (block_type == "ab") {
    if (v.is_number_integer()) return get_as<BipolarAnswer>(v);
    if (v == "same" || v == "different") return get_as<SameDifferentAnswer>(v);
    if (v == "A" || v == "B") return get_as<ChoiceAnswer>(v);
    throw AnswerError("expected \"same\", \"different\", \"A\", \"B\" or an integer from -3 to 3, got " + v.dump());
  }
  if (block_type == "mushra") return get_as<MushraAnswer>(v);
  if (block_type == "magnitude") return get_as<MagnitudeAnswer>(v);
  if (block_type == "identify") return get_as<IdentifyAnswer>(v);
  if (block_type == "rating") return get_as<RatingAnswer>(v);
  if (block_type == "adjust") return get_as<AdjustAnswer>(v);
  if (block_type == "staircase") return get_as<StaircaseAnswer>(v);
  if (block_type == "questionnaire") return get_as<QuestionnaireAnswer>(v);
  if (block_type == "bs1116") return get_as<Bs1116Answer>(v);
  if (block_type == "limits") return get_as<LimitsAnswer>(v);
  if (block_type == "tokens") return get_as<TokensAnswer>(v);
  if (block_type == "changepoint") return get_as<ChangepointAnswer>(v);
  throw AnswerError("no answer format for block type '" + block_type + "'");
}

Answer read_answer(const Block& block, const Trial& trial, const json& v) {
  switch (block.type) {
    case BlockType::instructions:
      return get_as<InstructionsAnswer>(v);
    case BlockType::ab: {
      const AbMode mode = std::get<AbBlock>(block.body).mode;
      if (mode == AbMode::same_different) return get_as<SameDifferentAnswer>(v);
      if (mode == AbMode::bipolar) return get_as<BipolarAnswer>(v);
      return get_as<ChoiceAnswer>(v);
    }
    case BlockType::mushra: {
      const auto a = get_as<MushraAnswer>(v);
      check_keys(a.scores, trial.stimuli, [](std::size_t, double) { return true; }, "a score from 0 to 100");
      return a;
    }
    case BlockType::magnitude: {
      const auto& mb = std::get<MagnitudeBlock>(block.body);
      if (mb.scale) {
        const auto x = finite(v);
        if (!x || *x < mb.scale->min || *x > mb.scale->max)
          throw AnswerError("expected a number from " + json(mb.scale->min).dump() + " to " + json(mb.scale->max).dump() +
                            " (the block's scale), got " + v.dump());
        return get_as<MagnitudeAnswer>(v);
      }
      const bool zero_allowed = mb.identical_pairs;  // "no difference"
      const auto v_ok = finite(v);
      if (!v_ok || !(*v_ok > 0.0 || (zero_allowed && *v_ok == 0.0)))
        throw AnswerError((zero_allowed ? "expected a number >= 0, got " : "expected a positive number, got ") + v.dump());
      return get_as<MagnitudeAnswer>(v);
    }
    case BlockType::identify:
      return IdentifyAnswer{one_of(v, std::get<IdentifyBlock>(block.body).labels)};
    case BlockType::rating: {
      const auto& r = std::get<RatingBlock>(block.body);
      const auto a = get_as<RatingAnswer>(v);
      std::vector<std::string> keys;
      for (const auto& attr : r.attributes) keys.push_back(attr.name);
      check_keys(a.points, keys, [&](std::size_t i, int x) { return x <= r.attributes[i].points; },
                 "an integer from 1 to the attribute's points");
      return a;
    }
    case BlockType::adjust: {
      const auto& adj = std::get<AdjustBlock>(block.body);
      const auto a = get_as<AdjustAnswer>(v);
      std::vector<std::string> keys;
      for (const auto& s : adj.sliders) keys.push_back(s.key);
      check_keys(a.values, keys, [&](std::size_t i, double x) {
        const Slider& s = adj.sliders[i];
        const double lo = std::min(s.min, s.max), hi = std::max(s.min, s.max);
        return x >= lo - 1e-9 * std::abs(hi - lo) && x <= hi + 1e-9 * std::abs(hi - lo);
      }, "a value within the slider's range");
      return a;
    }
    case BlockType::staircase:
      return get_as<StaircaseAnswer>(v);
    case BlockType::limits: {
      const auto& l = std::get<LimitsBlock>(block.body);
      auto a = get_as<LimitsAnswer>(v);
      if (a.parameter != l.parameter) throw AnswerError("the series varies '" + a.parameter + "', the block '" + l.parameter + "'");
      if (a.levels.empty()) throw AnswerError("a series has at least one trial");
      return a;
    }
    case BlockType::tokens: {
      const auto& t = std::get<TokensBlock>(block.body);
      auto a = get_as<TokensAnswer>(v);
      if (a.from != t.from || a.to != t.to)
        throw AnswerError("the series runs from " + std::to_string(a.from) + " to " + std::to_string(a.to) +
                          " modes, the block from " + std::to_string(t.from) + " to " + std::to_string(t.to));
      return a;
    }
    case BlockType::changepoint: {
      auto a = get_as<ChangepointAnswer>(v);
      if (!a.marks.empty() && a.marks.back() >= trial.stimuli.size())
        throw AnswerError("mark " + std::to_string(a.marks.back()) + " is past the sweep's " +
                          std::to_string(trial.stimuli.size()) + " sounds");
      return a;
    }
    case BlockType::questionnaire: {
      const auto& q = std::get<QuestionnaireBlock>(block.body);
      const auto a = get_as<QuestionnaireAnswer>(v);
      std::vector<std::string> keys;
      for (std::size_t i = 0; i < q.questions.size(); ++i) keys.push_back(question_id(q.questions[i], i));
      check_keys(a.answers, keys, [&](std::size_t i, const std::string& x) {
        const auto& opts = q.questions[i].options;
        return opts.empty() || std::find(opts.begin(), opts.end(), x) != opts.end();
      }, "text (or one of the question's options)");
      return a;
    }
    case BlockType::bs1116: {
      const auto a = get_as<Bs1116Answer>(v);
      check_keys(a.grades, trial.stimuli, [](std::size_t, double) { return true; }, "a grade from 1.0 to 5.0");
      return a;
    }
    case BlockType::unknown:
      break;
  }
  throw AnswerError("block '" + block.id + "' has an unknown type");
}

}  // namespace ms
