// Reading a modes CSV and applying the masking rule, with a bad mode named by its CSV line: shared by
// `modalstudy prune` and `modalstudy plot masking`.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "synthesis/input_error.hpp"
#include "synthesis/masking_pruning.hpp"
#include "synthesis/modes_csv.hpp"

namespace ms::cli {

inline std::pair<ModalModel, PruneResult> prune_modes_csv(const std::string& path, const PruneOptions& options) {
  std::vector<int> line_of_mode;
  ModalModel model = read_modes_csv(path, &line_of_mode);
  try {
    PruneResult result = prune_modes(model, options);
    return {std::move(model), std::move(result)};
  } catch (const PruneError& e) {
    const int line = e.mode() < line_of_mode.size() ? line_of_mode[e.mode()] : 0;
    throw InputError(SourceLocation{path, line, 0}, e.field() + " " + e.problem());
  }
}

}  // namespace ms::cli
