// Modes CSV: a header naming at least freq_hz, decay_per_s, amp (any order; optional phase_rad;
// other columns ignored), then one mode per row, read and written by synthesis/csv.hpp (RFC 4180,
// BOM, quotes). Errors name file:line:column.
#pragma once
#include <string>
#include <vector>

#include "synthesis/modal_model.hpp"

namespace ms {

// With `line_of_mode`, also gives the 1-based file line of each mode, so that a later check of a
// mode (e.g. pruning's "decay 0 has infinite power") can name its row.
ModalModel read_modes_csv(const std::string& path, std::vector<int>* line_of_mode = nullptr);
ModalModel parse_modes_csv(const std::string& text, const std::string& file_for_errors,
                           std::vector<int>* line_of_mode = nullptr);

// Writes freq_hz,decay_per_s,amp,phase_rad with 17 significant digits (atomically).
void write_modes_csv(const std::string& path, const ModalModel& model);

}  // namespace ms
