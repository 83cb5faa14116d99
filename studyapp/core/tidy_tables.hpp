// Per-block-type tidy tables made from the stored responses, one row per observation, in the column
// names the `modalstudy stats` commands read by default (mushra.csv: participant, trial, condition,
// rating; identify.csv: stimulus, response; staircase.csv: one row per step; ...).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "studyapp/core/results_store.hpp"

namespace ms {

// File name (e.g. "mushra.csv") -> RFC 4180 CSV text; only types that have responses appear.
std::map<std::string, std::string> tidy_tables(const std::vector<ResponseRow>& rows);

// The participant as exported: the code if the study allows personal fields, else "p<id>".
std::string exported_participant(const std::string& code, std::int64_t id, bool export_personal);

}  // namespace ms
