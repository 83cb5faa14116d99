// Nelder-Mead simplex search inside a box (Lagarias et al. 1998 coefficients: reflection 1, expansion
// 2, contraction 1/2, shrink 1/2). The estimation runs it in log parameters, where the metric is
// smoother and the box keeps every parameter positive. Derivative-free, because the metric's match
// scores are only piecewise smooth.
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

namespace ms {

struct BoxedSearchOptions {
  std::vector<double> lower, upper;  // the box; points are clamped into it
  std::vector<double> step;          // initial simplex edge per coordinate
  std::size_t max_evaluations = 300;
  double f_tolerance = 1e-6;  // stop when the simplex's values differ by less than this, relatively
  double x_tolerance = 1e-5;  // ... and its vertices by less than this per coordinate
};

struct BoxedSearchResult {
  std::vector<double> x;
  double value = 0.0;
  std::size_t iterations = 0;   // simplex steps
  std::size_t evaluations = 0;  // calls of f
};

BoxedSearchResult nelder_mead_boxed(const std::function<double(const std::vector<double>&)>& f,
                                    std::vector<double> start, const BoxedSearchOptions& options);

}  // namespace ms
