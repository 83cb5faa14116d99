// Error against a reference dataset (Sterling et al. 2019, Fig. 1.15): every subject rated the same
// sounds (the `match` cells, e.g. shape x material) in each dataset; per subject, dataset and cell the
// absolute difference between the dataset's rating and the reference dataset's, averaged over the
// cells, is one subject's error for that dataset. The result is a one-way repeated-measures design
// (within factor: the dataset, reference excluded) for rm_anova and pairwise_t_tests.
#pragma once

#include <string>
#include <vector>

#include "analysis/stats/rm_data.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {

struct ReferenceErrorColumns {
  std::string dv;          // the rating
  std::string subject;     // the listener
  std::string dataset;     // which dataset a sound is from
  std::string reference;   // the dataset level the others are compared with (e.g. "rec")
  std::vector<std::string> match;  // the columns naming the same sound across datasets
};

// Repeated ratings of one sound by one subject are averaged first. Throws InputError (FILE:LINE:COLUMN)
// for a missing column, a non-numeric rating, no row of the reference dataset, fewer than two other
// datasets, fewer than two subjects, or a subject who rated a sound in one dataset but not in the
// reference (or the other way round).
RmData reference_error_design(const TidyCsv& table, const ReferenceErrorColumns& columns);

}  // namespace ms
