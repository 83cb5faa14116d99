// Per-block-type tidy tables made from the stored responses, one row per observation, in the column
// names the `modalstudy stats` commands read by default (mushra.csv: participant, trial, condition,
// rating; identify.csv: stimulus, truth, response, correct; staircase.csv: one row per step; limits.csv: one row per trial of a series;
// tokens.csv: one row per comparison of a token series; changepoint.csv: one row per sound of a sweep; ...).
// The protocol of each study adds what the responses alone do not say: the identification truth,
// the stimuli's design factors (one column each), the modulus of magnitude blocks and where a
// staircase moved after its last answer.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"
#include "studyapp/core/results_store.hpp"

namespace ms {

// The key columns every table starts with.
const std::vector<std::string>& tidy_key_columns();  // study, participant, session, autopilot, block, trial

// File name (e.g. "mushra.csv") -> RFC 4180 CSV text; only types that have responses appear.
// `protocols` maps a study id to its parsed protocol; a study without one gets empty truth and
// factor cells (and NA for what only the protocol knows). A stored answer that cannot be read as its
// block type's answer (a store written by other software, or damaged) stays in responses.csv as
// stored but gets no typed row; `unreadable`, when given, receives one line naming it and why.
std::map<std::string, std::string> tidy_tables(const std::vector<ResponseRow>& rows,
                                               const std::map<std::string, Protocol>& protocols = {},
                                               std::vector<std::string>* unreadable = nullptr);

// An A/B trial's pair as the protocol writes it ([first, second]) and whether it was played the other
// way round: the schedule randomises which one is A. A bipolar score (B compared with A) and a
// chosen letter are turned back to the written order, so answers to one pair can be averaged.
struct WrittenPair {
  std::string first, second;
  bool swapped = false;
};
// nullopt when `block` is not an A/B block or has no such pair.
std::optional<WrittenPair> written_pair(const Block* block, const std::string& played_a, const std::string& played_b);

// The participant as exported: the code if the study allows personal fields, else "p<id>".
std::string exported_participant(const std::string& code, std::int64_t id, bool export_personal);

// The label an identify block expects for a stimulus: its `truth:` label, or the value of its truth
// map under the block's id, or the one value of the map that is among the block's labels; with no
// truth, the stimulus name when it is one of the labels; else "".
std::string identify_truth(const StimulusSource* stimulus, const std::string& stimulus_name, const Block& block);

}  // namespace ms
