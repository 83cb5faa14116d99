// One typed answer per block type, and its JSON as stored in the results store (the response value):
//   instructions   "ok"
//   ab             same_different: "same" | "different"; preference, abx, 2afc: "A" | "B" (abx: the one
//                  that is X); bipolar: integer -3..3 (B compared with A; with a block reference:
//                  positive when B is closer to the reference)
//   mushra         {"<stimulus>": 0..100, ...} for every stimulus of the trial (hidden reference too)
//   magnitude      number > 0 (the pair's dissimilarity, the modulus pair being the block's
//                  modulus_value); >= 0 with identical pairs; within [min, max] with a `scale`
//   identify       one of the block's labels
//   rating         {"<attribute>": 1..points, ...} for every attribute
//   adjust         {"<key>": value within the slider's range, ...} for every slider
//   staircase      {"parameter": key, "levels": [...], "correct": [...], "chosen": ["A"|"B", ...],
//                  "threshold": number|null}; answers stored before the choice was kept have no "chosen"
//   limits         {"parameter": key, "levels": [...], "responses": ["same"|"different", ...],
//                  "threshold": number|null}: one descending series, levels falling
//   tokens         {"from": K, "to": k, "responses": ["same"|"different", ...], "distinguished": [K, ...]}:
//                  one adaptive token series, one response per comparison (from - to of them, the
//                  comparison falling from from - 1 to `to`), the distinguished tokens as the rule gives them
//   changepoint    {"marks": [i, ...]}: the 0-based positions in the sweep of the sounds marked as a change
//                  of material, rising, never 0 (the first sound has nothing before it); may be empty
//   questionnaire  {"<question id>": "text or option", ...}
//   bs1116         {"<stimulus>": 1.0..5.0, ...} for A and B (the hidden reference under its own name)
// The views, the simulated listener and the session write answers through these types; the export, the
// experimenter view's pictures and the check before storing (response_format.hpp) read them back.
#pragma once
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "studyapp/core/protocol.hpp"
#include "studyapp/core/schedule.hpp"

namespace ms {

// Why a JSON value is not an answer to its trial (one line).
struct AnswerError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// One of a trial's two sounds, A (played first) or B; stored as "A" / "B".
enum class AbInterval { a, b };
std::string to_string(AbInterval i);
AbInterval other(AbInterval i);

struct InstructionsAnswer {};
struct SameDifferentAnswer { bool different = false; };
struct ChoiceAnswer { AbInterval chosen = AbInterval::a; };  // preference, ABX, 2AFC
struct BipolarAnswer { int score = 0; };                // -3..3
struct MushraAnswer { std::map<std::string, double> scores; };  // stimulus -> 0..100
struct MagnitudeAnswer { double value = 0.0; };
struct IdentifyAnswer { std::string label; };
struct RatingAnswer { std::map<std::string, int> points; };     // attribute -> 1..points
struct AdjustAnswer { std::map<std::string, double> values; };  // parameter-set key -> value
// A whole staircase track: per step the level presented, the interval the listener chose and whether
// that was right (the other interval held the comparison), and the track's threshold.
struct StaircaseAnswer {
  std::string parameter;
  std::vector<double> levels;
  std::vector<bool> correct;
  std::vector<AbInterval> chosen;  // one per step, or empty (stored before choices were kept)
  std::optional<double> threshold;
};
// A whole descending series of the method of limits: per trial the level presented and whether the
// listener heard a change, and the threshold (the last "same" level before the first "different").
struct LimitsAnswer {
  std::string parameter;
  std::vector<double> levels;
  std::vector<bool> different;
  std::optional<double> threshold;
};
// A whole adaptive token series (analysis/stats/token_series.hpp): whether each comparison was heard as
// different, in order; the tokens compared and the references follow from from, to and the answers.
struct TokensAnswer {
  int from = 0, to = 1;
  std::vector<bool> different;
};
// The sounds of a sweep marked as where the material changed (0-based, rising, > 0).
struct ChangepointAnswer { std::vector<std::size_t> marks; };
struct QuestionnaireAnswer { std::map<std::string, std::string> answers; };  // question id -> text
// BS.1116 impairment grades, 5.0 imperceptible ... 1.0 very annoying.
struct Bs1116Answer { std::map<std::string, double> grades; };  // stimulus -> 1.0..5.0
inline constexpr double kBs1116GradeMin = 1.0, kBs1116GradeMax = 5.0;

using Answer = std::variant<InstructionsAnswer, SameDifferentAnswer, ChoiceAnswer, BipolarAnswer, MushraAnswer,
                            MagnitudeAnswer, IdentifyAnswer, RatingAnswer, AdjustAnswer, StaircaseAnswer,
                            QuestionnaireAnswer, Bs1116Answer, LimitsAnswer, TokensAnswer, ChangepointAnswer>;

// The stored JSON of each type (nlohmann's to_json/from_json; from_json throws AnswerError).
void to_json(nlohmann::json& j, const InstructionsAnswer& a);
void to_json(nlohmann::json& j, const SameDifferentAnswer& a);
void to_json(nlohmann::json& j, const ChoiceAnswer& a);
void to_json(nlohmann::json& j, const BipolarAnswer& a);
void to_json(nlohmann::json& j, const MushraAnswer& a);
void to_json(nlohmann::json& j, const MagnitudeAnswer& a);
void to_json(nlohmann::json& j, const IdentifyAnswer& a);
void to_json(nlohmann::json& j, const RatingAnswer& a);
void to_json(nlohmann::json& j, const AdjustAnswer& a);
void to_json(nlohmann::json& j, const StaircaseAnswer& a);
void to_json(nlohmann::json& j, const QuestionnaireAnswer& a);
void to_json(nlohmann::json& j, const Bs1116Answer& a);
void to_json(nlohmann::json& j, const LimitsAnswer& a);
void to_json(nlohmann::json& j, const TokensAnswer& a);
void to_json(nlohmann::json& j, const ChangepointAnswer& a);
void to_json(nlohmann::json& j, const Answer& a);
void from_json(const nlohmann::json& j, InstructionsAnswer& a);
void from_json(const nlohmann::json& j, SameDifferentAnswer& a);
void from_json(const nlohmann::json& j, ChoiceAnswer& a);
void from_json(const nlohmann::json& j, BipolarAnswer& a);
void from_json(const nlohmann::json& j, MushraAnswer& a);
void from_json(const nlohmann::json& j, MagnitudeAnswer& a);
void from_json(const nlohmann::json& j, IdentifyAnswer& a);
void from_json(const nlohmann::json& j, RatingAnswer& a);
void from_json(const nlohmann::json& j, AdjustAnswer& a);
void from_json(const nlohmann::json& j, StaircaseAnswer& a);
void from_json(const nlohmann::json& j, QuestionnaireAnswer& a);
void from_json(const nlohmann::json& j, Bs1116Answer& a);
void from_json(const nlohmann::json& j, LimitsAnswer& a);
void from_json(const nlohmann::json& j, TokensAnswer& a);
void from_json(const nlohmann::json& j, ChangepointAnswer& a);

// A MUSHRA score as stored: a whole score (the slider's) as an integer, else the number.
nlohmann::json mushra_score_json(double score);

// A stored answer of a block type ("ab", "mushra", ... as the store names it) read by its shape alone
// (an A/B answer's mode from its value), for readers without the protocol. Throws AnswerError.
Answer read_stored_answer(const std::string& block_type, const nlohmann::json& value);

// `value` as an answer to `trial` of `block`: its shape for the block type (and A/B mode), and that it
// fits the block and trial (labels, keys, ranges). Throws AnswerError saying why not.
Answer read_answer(const Block& block, const Trial& trial, const nlohmann::json& value);

// Question id of a questionnaire item (written id, or "q<n>" 1-based).
std::string question_id(const Question& q, std::size_t index);

}  // namespace ms
