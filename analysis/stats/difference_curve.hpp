// Fig. 4 of van den Doel et al. 2002: the perceived difference between the reference (the real sound)
// and each synthetic token, against the token's number of modes, from the magnitude ratings of
// Experiment 3. The paper plots its 1-10 answers (1 = identical) on a 0-9 scale ("0 being
// indistinguishable"): the rating plus an offset of -1.
//
// Per listener, the mean of their ratings of the pair (reference, token) in either order (repeats
// included), plus `offset`; then the arithmetic mean and standard deviation over the listeners (the
// figure is "averaged over 8 subjects"). Ratings are taken as given, not normalised by a modulus: on a
// bounded scale the number itself is the answer the figure plots.
//
// The token's x value (its number of modes) is read from the `x` column of the row in which the token is
// rated against itself: in the export's magnitude.csv a design factor is written where both sounds of a
// pair share it, so a stimulus's own `factors: {modes: "9"}` appears on its identical pair (`pairs:
// all_with_identical`, as the paper's 78 pairs).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/stats/magnitude_estimation.hpp"
#include "synthesis/tidy_csv.hpp"

namespace ms {

struct DifferencePoint {
  std::string token;
  std::string x;              // the token's `x` value ("" without an x column)
  std::size_t listeners = 0;
  double mean = 0, sd = 0;    // over listeners (sd NaN for one listener)
};

// Points in order of x when every x is a number (else of first appearance). InputError for a reference
// that no row names, a rating that is not a number, a token whose identical pair is missing or has an
// empty or ambiguous x; std columns as magnitude_estimation.
std::vector<DifferencePoint> difference_to_reference(const TidyCsv& table, const MagnitudeColumns& columns,
                                                     const std::string& reference, double offset,
                                                     const std::string& x_column = "");

}  // namespace ms
