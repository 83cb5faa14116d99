// A repeated-measures design in wide form: one row of cell means per subject, built from a tidy
// (long) table, averaging repeated observations per cell as afex::aov_ez does (fun_aggregate = mean).
#pragma once
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

struct RmFactor {
  std::string name;
  std::vector<std::string> levels;  // in order of first appearance in the data
};

struct RmData {
  std::vector<RmFactor> within;   // model order; cell index is row-major (first factor slowest)
  std::vector<RmFactor> between;  // at most a few; every combination must hold subjects
  std::vector<std::string> subjects;
  Eigen::MatrixXd cell_mean;               // subjects x cells
  Eigen::MatrixXi between_level;           // subjects x between factors (level index)
  std::size_t cells() const;               // product of within level counts (1 if none)
};

struct RmColumns {
  std::string dv, subject;
  std::vector<std::string> within, between;
};

// Builds the wide design from a long table. `notices` receives one line per thing the caller
// should know (e.g. cells averaged). Throws InputError (FILE:LINE:COLUMN) for a missing column, a
// non-numeric dv, a subject without an observation in some within cell, a subject whose between
// level changes, fewer than two subjects, or a factor with a single level.
RmData rm_data_from_table(const TidyCsv& table, const RmColumns& columns, std::vector<std::string>& notices);

}  // namespace ms
