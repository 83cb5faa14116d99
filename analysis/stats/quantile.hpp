// Sample quantiles and the median, as R's stats::quantile (default type 7) and stats::median.
//
//   type 7 (Hyndman & Fan 1996, definition 7): sort x to x_(1) <= ... <= x_(n); h = (n - 1) p + 1;
//   Q(p) = x_(floor h) + (h - floor h) (x_(floor h + 1) - x_(floor h)).
//   median = Q(0.5): the middle value for odd n, the mean of the two middle values for even n.
#pragma once
#include <vector>

namespace ms {

// p in [0, 1]; x non-empty (std::invalid_argument otherwise). NaNs are not allowed.
double quantile(std::vector<double> x, double p);
double median(std::vector<double> x);

}  // namespace ms
