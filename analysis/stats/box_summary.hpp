// The numbers of a box-and-whisker plot (Tukey's box, as R's boxplot draws it with range = 1.5 and as
// matplotlib's boxplot does): the quartiles are R's default quantiles (type 7, quantile.hpp); the
// whiskers reach the furthest observations within 1.5 IQR of the box; observations beyond are outliers.
#pragma once
#include <cstddef>
#include <vector>

namespace ms {

struct BoxSummary {
  std::size_t n = 0;
  double lower_whisker = 0, q1 = 0, median = 0, q3 = 0, upper_whisker = 0;
  std::vector<double> outliers;  // ascending
};

// x non-empty and without NaN (std::invalid_argument otherwise).
BoxSummary box_summary(std::vector<double> x);

}  // namespace ms
