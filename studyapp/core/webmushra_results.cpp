// webMUSHRA's result tables from the stored answers; see webmushra_results.hpp.
#include "studyapp/core/webmushra_results.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "studyapp/core/answers.hpp"
#include "studyapp/core/tidy_tables.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/csv.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

namespace {

// The name webMUSHRA gives a graded stimulus: "anchor35", "anchor70" for the 3.5 / 7 kHz low-pass of
// the reference, else its own.
std::string anchor_or_own(const Protocol* p, const std::string& reference, const std::string& name) {
  const StimulusSource* s = p ? p->find_stimulus(name) : nullptr;
  if (s && s->kind == StimulusKind::derived && s->derive_from.name == reference) {
    if (s->lowpass_hz == 3500) return "anchor35";
    if (s->lowpass_hz == 7000) return "anchor70";
  }
  return name;
}

// The name webMUSHRA gives a MUSHRA stimulus: "reference", "anchor35", "anchor70", else its own.
std::string mushra_stimulus(const Protocol* p, const MushraBlock* block, const std::string& name) {
  if (!block || !block->reference) return name;
  if (name == block->reference->name) return "reference";
  return anchor_or_own(p, block->reference->name, name);
}

std::string milliseconds(double ms) { return std::to_string(std::llround(ms)); }

}  // namespace

std::map<std::string, std::string> webmushra_tables(const std::vector<ResponseRow>& rows,
                                                    const std::map<std::string, Protocol>& protocols,
                                                    std::vector<std::string>* notices) {
  // The questionnaire columns: every question id of the studies' questionnaire blocks, in file order,
  // and each session's answers to them.
  std::vector<std::string> questions;
  for (const auto& [id, p] : protocols)
    for (const Block& b : p.blocks)
      if (const auto* q = std::get_if<QuestionnaireBlock>(&b.body))
        for (std::size_t i = 0; i < q->questions.size(); ++i) {
          const std::string qid = question_id(q->questions[i], i);
          if (std::find(questions.begin(), questions.end(), qid) == questions.end()) questions.push_back(qid);
        }
  std::map<std::int64_t, std::map<std::string, std::string>> answers;  // session -> question -> answer
  for (const ResponseRow& r : rows)
    if (r.block_type == "questionnaire") try {
        const Answer a = read_stored_answer(r.block_type, nlohmann::json::parse(r.value_json));
        for (const auto& [q, text] : std::get<QuestionnaireAnswer>(a).answers) answers[r.session][q] = text;
      } catch (const std::exception&) {
        // Unreadable answers are named where their own table is written (the tidy export).
      }

  static const std::map<std::string, std::vector<std::string>> kColumns{
      {"mushra.csv", {"trial_id", "rating_stimulus", "rating_score", "rating_time", "rating_comment"}},
      {"paired_comparison.csv",
       {"trial_id", "choice_reference", "choice_non_reference", "choice_answer", "choice_time", "choice_comment"}},
      {"lss.csv", {"trial_id", "stimuli_rating", "stimuli", "rating_time"}},
      {"bs1116.csv", {"trial_id", "rating_reference", "rating_non_reference", "rating_reference_score",
                      "rating_non_reference_score", "rating_time", "choice_comment"}}};
  std::map<std::string, std::string> out;
  std::set<std::string> left_out;
  for (const ResponseRow& r : rows) {
    const auto pit = protocols.find(r.study);
    const Protocol* protocol = pit == protocols.end() ? nullptr : &pit->second;
    const Block* block = protocol ? protocol->find_block(r.block_id) : nullptr;
    const auto add = [&](const std::string& table, std::vector<std::string> cells) {
      std::string& csv = out[table];
      if (csv.empty()) {
        std::vector<std::string> header{"session_test_id"};
        header.insert(header.end(), questions.begin(), questions.end());
        header.push_back("session_uuid");
        header.insert(header.end(), kColumns.at(table).begin(), kColumns.at(table).end());
        csv = csv::line(header);
      }
      std::vector<std::string> line{r.study};
      const auto session = answers.find(r.session);
      for (const std::string& q : questions) {
        std::string cell;
        if (session != answers.end())
          if (const auto a = session->second.find(q); a != session->second.end()) cell = a->second;
        line.push_back(cell);
      }
      line.push_back(r.study + "-" + std::to_string(r.session));
      line.push_back(r.block_id);
      line.insert(line.end(), cells.begin(), cells.end());
      csv += csv::line(line);
    };
    Answer answer;
    try {
      answer = read_stored_answer(r.block_type, nlohmann::json::parse(r.value_json));
    } catch (const std::exception&) {
      continue;  // named by the tidy export, which keeps it in responses.csv
    }
    const auto stimuli = nlohmann::json::parse(r.stimuli_json);
    const auto at = [&](std::size_t i) { return i < stimuli.size() ? stimuli[i].get<std::string>() : std::string(); };
    if (const auto* mushra = std::get_if<MushraAnswer>(&answer)) {
      const auto* mb = block ? std::get_if<MushraBlock>(&block->body) : nullptr;
      for (const auto& [name, score] : mushra->scores)
        add("mushra.csv", {mushra_stimulus(protocol, mb, name), mushra_score_json(score).dump(), milliseconds(r.rt_ms), ""});
    } else if (const auto* choice = std::get_if<ChoiceAnswer>(&answer);
               choice && block && std::get_if<AbBlock>(&block->body) &&
               std::get<AbBlock>(block->body).mode == AbMode::preference) {
      const std::optional<WrittenPair> pair = written_pair(block, at(0), at(1));
      if (!pair) continue;
      const std::string chosen = choice->chosen == AbInterval::a ? at(0) : at(1);
      add("paired_comparison.csv", {pair->first, pair->second, chosen, milliseconds(r.rt_ms), ""});
    } else if (const auto* bs = std::get_if<Bs1116Answer>(&answer);
               bs && block && std::get_if<Bs1116Block>(&block->body)) {
      const auto& tb = std::get<Bs1116Block>(block->body);
      const std::string condition = at(0) == tb.reference.name ? at(1) : at(0);
      const auto gr = bs->grades.find(tb.reference.name), gc = bs->grades.find(condition);
      if (gr == bs->grades.end() || gc == bs->grades.end()) continue;
      add("bs1116.csv", {"reference", anchor_or_own(protocol, tb.reference.name, condition), csv::number(gr->second),
                         csv::number(gc->second), milliseconds(r.rt_ms), ""});
    } else if (const auto* rating = std::get_if<RatingAnswer>(&answer); rating && rating->points.size() == 1) {
      add("lss.csv", {std::to_string(rating->points.begin()->second), at(0), milliseconds(r.rt_ms)});
    } else if (r.block_type != "instructions" && r.block_type != "questionnaire") {
      left_out.insert(r.study + " block '" + r.block_id + "' (" + r.block_type + ")");
    }
  }
  if (notices)
    for (const std::string& b : left_out) notices->push_back(b + ": no webMUSHRA table holds it (see the tidy export)");
  return out;
}

ExportSummary export_webmushra(const std::string& db, const std::string& out_dir) {
  const ResultsStore store(db, ResultsStore::Mode::read_only);
  const std::vector<ResponseRow> rows = store.response_rows();
  ExportSummary summary;
  summary.responses = rows.size();
  const auto tables = webmushra_tables(rows, stored_protocols(store), &summary.notices);
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw InputError(SourceLocation{out_dir, 0, 0}, "cannot create folder: " + ec.message());
  for (const auto& [name, text] : tables) {
    write_file_atomically((std::filesystem::path(out_dir) / name).string(), text);
    summary.tables.push_back(name);
  }
  return summary;
}

}  // namespace ms
