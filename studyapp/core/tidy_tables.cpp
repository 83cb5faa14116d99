// tidy_tables: each stored answer read as its typed answer (answers.hpp) and laid out in long rows.
#include "studyapp/core/tidy_tables.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

#include "analysis/stats/token_series.hpp"
#include "studyapp/core/answers.hpp"
#include "studyapp/core/response_format.hpp"
#include "studyapp/core/staircase_track.hpp"
#include "synthesis/csv.hpp"

namespace ms {

namespace {

// A cell as the stored JSON writes the value: "20.0" for a stored double, "87" for an integer.
std::string cell(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_null()) return "NA";
  return v.dump();
}

// One row per step of a track. Where the track moved after each answer is the rule replayed, so the
// last trial's reversal counts; the interval chosen only where the store keeps it.
std::vector<std::vector<std::string>> staircase_rows(const StaircaseAnswer& a, const StaircaseBlock* block,
                                                     const std::string& stimulus, bool with_chosen) {
  const std::size_t n = a.levels.size();
  std::vector<std::string> next(n, "NA");
  for (std::size_t i = 0; i + 1 < n; ++i) next[i] = cell(a.levels[i + 1]);
  if (block) {
    StaircaseTrack track(block->start, block->step, block->down, block->up, block->reversals);
    bool same = true;
    for (std::size_t i = 0; i < n; ++i) {
      same = same && track.level() == a.levels[i];
      track.record(a.correct[i]);
    }
    if (same && n > 0) next.back() = csv::number(track.level());
  }
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < n; ++i) {
    rows.push_back({stimulus, a.parameter, std::to_string(i), cell(a.levels[i]), next[i], a.correct[i] ? "1" : "0",
                    a.threshold ? cell(*a.threshold) : "NA"});
    if (with_chosen) rows.back().push_back(a.chosen.empty() ? "NA" : to_string(a.chosen[i]));
  }
  return rows;
}

// One row per trial of a descending series, in presentation order (`stats limits --level level
// --response response --track participant,block,trial` reads it as written). `censored`: the series
// never heard a change, so its threshold is only an upper bound (its last level).
std::vector<std::vector<std::string>> limits_rows(const LimitsAnswer& a, const std::string& stimulus,
                                                  const std::string& reference) {
  const bool censored = std::find(a.different.begin(), a.different.end(), true) == a.different.end();
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < a.levels.size(); ++i)
    rows.push_back({stimulus, reference, a.parameter, std::to_string(i), cell(a.levels[i]),
                    a.different[i] ? "different" : "same", a.different[i] ? "1" : "0",
                    a.threshold ? cell(*a.threshold) : "NA", censored ? "1" : "0"});
  return rows;
}

// One row per comparison of a token series, in order: the reference's and the comparison's number of
// modes, the answer, and the series' summary (distinguished tokens and the ceiling, the number of tokens),
// so `stats tokens` reads Table 2 from the rows alone.
std::vector<std::vector<std::string>> tokens_rows(const TokensAnswer& a, const std::string& stimulus) {
  TokenSeries series(a.from, a.to);
  for (bool d : a.different) series.record(d);
  const std::vector<int> comparisons = series.comparisons();
  const std::string distinguished = std::to_string(series.distinguished().size()), tokens = std::to_string(series.tokens());
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < a.different.size(); ++i)
    rows.push_back({stimulus, std::to_string(i), std::to_string(series.references()[i]), std::to_string(comparisons[i]),
                    a.different[i] ? "different" : "same", a.different[i] ? "1" : "0", distinguished, tokens});
  return rows;
}

// The answer in the written order: a bipolar score negated, a chosen letter exchanged, when swapped.
std::string oriented_cell(const Answer& answer, bool swapped) {
  if (const auto* bipolar = std::get_if<BipolarAnswer>(&answer)) return std::to_string(swapped ? -bipolar->score : bipolar->score);
  if (const auto* choice = std::get_if<ChoiceAnswer>(&answer)) return to_string(swapped ? other(choice->chosen) : choice->chosen);
  return cell(answer);
}

// Does any staircase answer keep the intervals chosen? Stores made before they were kept export the
// staircase table without the `chosen` column, as they always did.
bool any_staircase_choices(const std::vector<ResponseRow>& rows) {
  return std::any_of(rows.begin(), rows.end(), [](const ResponseRow& r) {
    return r.block_type == "staircase" && nlohmann::json::parse(r.value_json).contains("chosen");
  });
}

// Does any magnitude block use a bounded scale? Only then does magnitude.csv get the scale's columns
// (tables of open ratio scales stay as they always were).
bool any_bounded_scale(const std::map<std::string, Protocol>& protocols) {
  for (const auto& [id, p] : protocols)
    for (const Block& b : p.blocks)
      if (const auto* m = std::get_if<MagnitudeBlock>(&b.body); m && m->scale) return true;
  return false;
}

// Does any adjust block's target state the parameters behind it (`truth:` on the target stimulus)? Only
// then does adjust.csv get `target` and `truth` (tables of other adjust blocks stay as they always were).
bool any_adjust_truth(const std::map<std::string, Protocol>& protocols) {
  for (const auto& [id, p] : protocols)
    for (const Block& b : p.blocks)
      if (const auto* a = std::get_if<AdjustBlock>(&b.body); a && a->target)
        if (const StimulusSource* t = p.find_stimulus(a->target->name); t && !t->truth.empty()) return true;
  return false;
}

// The value an adjust block's target states for `key` (its `truth:`), "NA" when it states none.
std::string adjust_truth(const Protocol* protocol, const AdjustBlock* block, const std::string& key) {
  if (!protocol || !block || !block->target) return "NA";
  if (const StimulusSource* t = protocol->find_stimulus(block->target->name))
    for (const auto& [name, value] : t->truth)
      if (name == key) return value;
  return "NA";
}

const std::vector<std::string> kBase{"study", "participant", "session", "autopilot", "block", "trial"};

const std::map<std::string, std::vector<std::string>>& type_columns() {
  static const std::map<std::string, std::vector<std::string>> c{
      {"ab", {"stimulus_a", "stimulus_b", "stimulus_x", "response", "correct", "pair_first", "pair_second",
              "swapped", "response_oriented"}},
      {"mushra", {"condition", "rating"}},
      {"magnitude", {"first", "second", "value", "modulus_a", "modulus_b", "modulus_value"}},  // + scale_min, scale_max
      {"identify", {"stimulus", "truth", "response", "correct"}},
      {"rating", {"stimulus", "attribute", "value"}},
      {"adjust", {"stimulus", "key", "value", "plays", "rt_ms"}},  // + target, truth
      {"staircase", {"stimulus", "parameter", "step", "level", "next_level", "correct", "threshold"}},  // + chosen
      {"limits", {"stimulus", "reference", "parameter", "step", "level", "response", "different", "threshold", "censored"}},
      {"tokens", {"stimulus", "step", "reference", "comparison", "response", "different", "distinguished", "tokens"}},
      {"changepoint", {"stimulus", "parameter", "position", "value", "marked", "marks"}},
      {"questionnaire", {"question", "answer"}},
      {"bs1116", {"condition", "reference", "hidden_reference", "condition_grade", "reference_grade", "diffgrade"}}};
  return c;
}

// Factor names over every protocol, in file order.
std::vector<std::string> factor_names(const std::map<std::string, Protocol>& protocols) {
  std::vector<std::string> names;
  for (const auto& [id, p] : protocols)
    for (const StimulusSource& s : p.stimuli)
      for (const auto& [name, level] : s.factors)
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

std::string factor_of(const StimulusSource* s, const std::string& name) {
  if (!s) return "";
  for (const auto& [n, level] : s->factors)
    if (n == name) return level;
  return "";
}

}  // namespace

const std::vector<std::string>& tidy_key_columns() { return kBase; }

std::optional<WrittenPair> written_pair(const Block* block, const std::string& played_a, const std::string& played_b) {
  const auto* ab = block ? std::get_if<AbBlock>(&block->body) : nullptr;
  if (!ab) return std::nullopt;
  for (const StimulusPair& p : ab->pairs) {
    if (p[0].name == played_a && p[1].name == played_b) return WrittenPair{p[0].name, p[1].name, false};
    if (p[0].name == played_b && p[1].name == played_a) return WrittenPair{p[0].name, p[1].name, true};
  }
  return std::nullopt;
}

std::string exported_participant(const std::string& code, std::int64_t id, bool export_personal) {
  // Codes are often names or initials: opaque ids unless the study allows personal fields.
  return export_personal ? code : "p" + std::to_string(id);
}

std::string identify_truth(const StimulusSource* stimulus, const std::string& stimulus_name, const Block& block) {
  const auto* ib = std::get_if<IdentifyBlock>(&block.body);
  const std::vector<std::string> labels = ib ? ib->labels : std::vector<std::string>{};
  const auto is_label = [&](const std::string& v) { return std::find(labels.begin(), labels.end(), v) != labels.end(); };
  if (stimulus && !stimulus->truth.empty()) {
    for (const auto& [attribute, label] : stimulus->truth)
      if (attribute.empty() || attribute == block.id) return label;
    std::string found;
    int matches = 0;
    for (const auto& [attribute, label] : stimulus->truth)
      if (is_label(label)) {
        found = label;
        ++matches;
      }
    return matches == 1 ? found : "";
  }
  return is_label(stimulus_name) ? stimulus_name : "";
}

std::map<std::string, std::string> tidy_tables(const std::vector<ResponseRow>& rows,
                                               const std::map<std::string, Protocol>& protocols,
                                               std::vector<std::string>* unreadable) {
  std::vector<std::string> factors = factor_names(protocols);
  const bool staircase_choices = any_staircase_choices(rows);
  const bool scale_columns = any_bounded_scale(protocols);
  const bool truth_columns = any_adjust_truth(protocols);
  std::map<std::string, std::string> out;
  for (const ResponseRow& r : rows) {
    const auto cols = type_columns().find(r.block_type);
    if (cols == type_columns().end()) continue;  // instructions
    const auto pit = protocols.find(r.study);
    const Protocol* protocol = pit == protocols.end() ? nullptr : &pit->second;
    const Block* block = protocol ? protocol->find_block(r.block_id) : nullptr;
    std::string& csv = out[r.block_type + ".csv"];
    if (csv.empty()) {
      std::vector<std::string> header = kBase;
      header.insert(header.end(), cols->second.begin(), cols->second.end());
      if (r.block_type == "staircase" && staircase_choices) header.push_back("chosen");
      if (r.block_type == "magnitude" && scale_columns) header.insert(header.end(), {"scale_min", "scale_max"});
      if (r.block_type == "adjust" && truth_columns) header.insert(header.end(), {"target", "truth"});
      // A factor named like a column gets a suffix rather than a duplicate column.
      for (const std::string& f : factors)
        header.push_back(std::find(header.begin(), header.end(), f) == header.end() ? f : f + "_factor");
      csv = csv::line(header);
    }
    const std::vector<std::string> k{r.study, exported_participant(r.participant_code, r.participant, r.export_personal),
                                     std::to_string(r.session), r.autopilot ? "1" : "0", r.block_id,
                                     std::to_string(r.trial_index)};
    const auto stimulus = [&](const std::string& name) { return protocol ? protocol->find_stimulus(name) : nullptr; };
    // The factor cells of a row about one stimulus, or of a pair (the level both share, else empty).
    const auto add = [&](std::vector<std::string> rest, const std::string& a, const std::string& b = "") {
      std::vector<std::string> line = k;
      line.insert(line.end(), rest.begin(), rest.end());
      for (const std::string& f : factors) {
        const std::string la = factor_of(stimulus(a), f);
        line.push_back(b.empty() || factor_of(stimulus(b), f) == la ? la : "");
      }
      csv += csv::line(line);
    };
    const auto s = nlohmann::json::parse(r.stimuli_json);
    Answer answer;
    try {
      answer = read_stored_answer(r.block_type, nlohmann::json::parse(r.value_json));
    } catch (const std::exception& e) {  // AnswerError, or JSON the store should never hold
      if (unreadable)
        unreadable->push_back("session " + std::to_string(r.session) + ", block '" + r.block_id + "', trial " +
                              std::to_string(r.trial_index) + ": answer not in " + r.block_type + ".csv (" +
                              e.what() + ")");
      continue;
    }
    const auto at = [&](std::size_t i) { return i < s.size() ? s[i].get<std::string>() : std::string(); };
    if (r.block_type == "ab") {
      std::string correct = "NA";
      const auto* choice = std::get_if<ChoiceAnswer>(&answer);
      if (s.size() == 3 && choice) correct = abx_correct(s, choice->chosen) ? "1" : "0";
      const std::optional<WrittenPair> written = written_pair(block, at(0), at(1));
      add({at(0), at(1), at(2), cell(answer), correct, written ? written->first : "NA",
           written ? written->second : "NA", written ? (written->swapped ? "1" : "0") : "NA",
           written ? oriented_cell(answer, written->swapped) : "NA"},
          at(0), at(1));
    } else if (const auto* mushra = std::get_if<MushraAnswer>(&answer)) {
      // The hidden reference is rated under its own name (`stats mushra --reference NAME`).
      for (const auto& [name, score] : mushra->scores) add({name, cell(mushra_score_json(score))}, name);
    } else if (const auto* magnitude = std::get_if<MagnitudeAnswer>(&answer)) {
      const auto* mb = block ? std::get_if<MagnitudeBlock>(&block->body) : nullptr;
      std::vector<std::string> modulus{"", "", "NA"};
      if (mb && mb->modulus) modulus = {(*mb->modulus)[0].name, (*mb->modulus)[1].name, csv::number(mb->modulus_value)};
      std::vector<std::string> row{at(0), at(1), cell(magnitude->value), modulus[0], modulus[1], modulus[2]};
      const bool bounded = mb && mb->scale;
      if (scale_columns)
        row.insert(row.end(), {bounded ? csv::number(mb->scale->min) : "NA", bounded ? csv::number(mb->scale->max) : "NA"});
      add(std::move(row), at(0), at(1));
    } else if (const auto* identify = std::get_if<IdentifyAnswer>(&answer)) {
      const std::string truth = block ? identify_truth(stimulus(at(0)), at(0), *block) : "";
      add({at(0), truth, identify->label, truth.empty() ? "NA" : (truth == identify->label ? "1" : "0")}, at(0));
    } else if (const auto* rating = std::get_if<RatingAnswer>(&answer)) {
      for (const auto& [attr, value] : rating->points) add({at(0), attr, std::to_string(value)}, at(0));
    } else if (const auto* adjust = std::get_if<AdjustAnswer>(&answer)) {
      const auto* ab = block ? std::get_if<AdjustBlock>(&block->body) : nullptr;
      for (const auto& [key, value] : adjust->values) {
        std::vector<std::string> row{at(0), key, cell(value), std::to_string(r.plays), cell(r.rt_ms)};
        if (truth_columns)
          row.insert(row.end(), {ab && ab->target ? ab->target->name : "NA", adjust_truth(protocol, ab, key)});
        add(std::move(row), at(0));
      }
    } else if (const auto* track = std::get_if<StaircaseAnswer>(&answer)) {
      const auto* sb = block ? std::get_if<StaircaseBlock>(&block->body) : nullptr;
      for (std::vector<std::string>& row : staircase_rows(*track, sb, at(0), staircase_choices)) add(std::move(row), at(0));
    } else if (const auto* series = std::get_if<LimitsAnswer>(&answer)) {
      for (std::vector<std::string>& row : limits_rows(*series, at(0), at(1))) add(std::move(row), at(0));
    } else if (const auto* tokens = std::get_if<TokensAnswer>(&answer)) {
      for (std::vector<std::string>& row : tokens_rows(*tokens, at(0))) add(std::move(row), at(0));
    } else if (const auto* change = std::get_if<ChangepointAnswer>(&answer)) {
      // One row per sound of the sweep, marked or not, so a sweep without marks still counts as heard.
      const auto* cb = block ? std::get_if<ChangepointBlock>(&block->body) : nullptr;
      const auto& marks = change->marks;
      for (std::size_t i = 0; i < s.size(); ++i) {
        const bool marked = std::find(marks.begin(), marks.end(), i) != marks.end();
        add({at(i), cb ? cb->parameter : "NA", std::to_string(i),
             cb && i < cb->values.size() ? csv::number(cb->values[i]) : "NA", marked ? "1" : "0",
             std::to_string(marks.size())},
            at(i));
      }
    } else if (const auto* bs = std::get_if<Bs1116Answer>(&answer)) {
      // Which of A and B was the hidden reference comes from the block (the stored trial names both).
      const auto* tb = block ? std::get_if<Bs1116Block>(&block->body) : nullptr;
      const std::string ref = tb ? tb->reference.name : "";
      const bool ref_is_a = !ref.empty() && at(0) == ref, ref_is_b = !ref.empty() && at(1) == ref;
      const std::string condition = ref_is_a ? at(1) : ref_is_b ? at(0) : "";
      const auto grade = [&](const std::string& name) {
        const auto g = bs->grades.find(name);
        return g == bs->grades.end() ? std::optional<double>() : std::optional<double>(g->second);
      };
      const auto gc = grade(condition), gr = grade(ref);
      if (ref_is_a == ref_is_b || !gc || !gr) {
        add({"NA", ref.empty() ? "NA" : ref, "NA", "NA", "NA", "NA"}, "");
      } else {
        const double diffgrade = std::round((*gc - *gr) * 1e6) / 1e6;  // grades differ in tenths
        add({condition, ref, ref_is_a ? "A" : "B", csv::number(*gc), csv::number(*gr), csv::number(diffgrade)}, condition);
      }
    } else if (const auto* questionnaire = std::get_if<QuestionnaireAnswer>(&answer)) {
      for (const auto& [q, text] : questionnaire->answers) add({q, text}, "");
    }
  }
  return out;
}

}  // namespace ms
