// A study's answers as webMUSHRA's result tables, so analysis scripts written for webMUSHRA read them
// (the column names of its service/write.php, with session_uuid as newer versions write it):
//   mushra.csv             session_test_id, <questionnaire>, session_uuid, trial_id, rating_stimulus,
//                          rating_score, rating_time, rating_comment
//   paired_comparison.csv  ..., trial_id, choice_reference, choice_non_reference, choice_answer,
//                          choice_time, choice_comment
//   lss.csv                ..., trial_id, stimuli_rating, stimuli, rating_time
//   bs1116.csv             ..., trial_id, rating_reference, rating_non_reference, rating_reference_score,
//                          rating_non_reference_score, rating_time, choice_comment (one row per trial:
//                          the hidden reference's grade and the condition's)
// session_test_id is the study id, trial_id the block id, session_uuid the study and session number;
// the questionnaire columns are the question ids of the study's questionnaire blocks, filled with the
// session's answers. MUSHRA ratings of the hidden reference are named "reference" and those of the
// 3.5 / 7 kHz low-passed reference "anchor35" / "anchor70", as webMUSHRA names them. Paired
// comparisons are the `preference` A/B blocks (reference = the pair's first stimulus as written),
// Likert ratings the one-attribute rating blocks (the point, 1..points); other blocks have no
// webMUSHRA table and are named in the notices.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "studyapp/core/export.hpp"
#include "studyapp/core/protocol.hpp"
#include "studyapp/core/results_store.hpp"

namespace ms {

// File name -> RFC 4180 CSV text; only tables with rows appear.
std::map<std::string, std::string> webmushra_tables(const std::vector<ResponseRow>& rows,
                                                    const std::map<std::string, Protocol>& protocols,
                                                    std::vector<std::string>* notices = nullptr);

// Reads `db` (never modified) and writes the tables into `out_dir` (created if missing), each
// atomically; nothing is written when the store cannot be read.
ExportSummary export_webmushra(const std::string& db, const std::string& out_dir);

}  // namespace ms
