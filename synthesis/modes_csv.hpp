// Modes CSV: a header naming at least freq_hz, decay_per_s, amp (any order; optional phase_rad;
// other columns ignored), then one mode per row. Errors name file:line:column.
#pragma once
#include <string>

#include "synthesis/modal_model.hpp"

namespace ms {

ModalModel read_modes_csv(const std::string& path);
ModalModel parse_modes_csv(const std::string& text, const std::string& file_for_errors);

// Writes freq_hz,decay_per_s,amp,phase_rad with 17 significant digits (atomically).
void write_modes_csv(const std::string& path, const ModalModel& model);

}  // namespace ms
