// Dissimilarity matrices for MDS, read from tidy CSV: either square (header: a label column, then
// one column per stimulus in the same order as the rows) or long (one row per rated pair, repeated
// ratings of a pair averaged, both orders of a pair pooled).
#pragma once
#include <Eigen/Dense>

#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"

namespace ms {

struct DissimilarityMatrix {
  std::vector<std::string> labels;
  Eigen::MatrixXd values;  // symmetric, zero diagonal, non-negative
  std::size_t averaged_pairs = 0;  // long form: pairs with more than one rating
};

// Square form. Throws InputError at the offending cell for a label mismatch, a negative value, a
// non-zero diagonal or an asymmetric pair (tolerance 1e-9 relative; the mean of the two is used).
DissimilarityMatrix dissimilarity_from_square(const TidyCsv& table);

// Long form from three columns. Throws InputError for a pair never rated or a negative value.
DissimilarityMatrix dissimilarity_from_pairs(const TidyCsv& table, const std::string& first, const std::string& second,
                                             const std::string& value);

}  // namespace ms
