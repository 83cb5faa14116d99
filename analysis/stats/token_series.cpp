// TokenSeries: the adaptive rule; see token_series.hpp.
#include "analysis/stats/token_series.hpp"

#include <stdexcept>
#include <string>

namespace ms {

TokenSeries::TokenSeries(int from, int to) : from_(from), to_(to), reference_(from) {
  if (!(to >= 1 && from > to))
    throw std::invalid_argument("a token sequence runs from more modes down to at least 1 (from " +
                                std::to_string(from) + " to " + std::to_string(to) + ")");
}

// Each token but the first is compared once, in falling order: the next one is one below the last.
int TokenSeries::comparison() const { return from_ - 1 - int(different_.size()); }

void TokenSeries::record(bool different) {
  if (finished()) throw std::logic_error("TokenSeries::record: the series has compared every token");
  const int compared = comparison();
  references_.push_back(reference_);
  different_.push_back(different);
  if (different) reference_ = compared;
}

std::vector<int> TokenSeries::comparisons() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < different_.size(); ++i) out.push_back(from_ - 1 - int(i));
  return out;
}

std::vector<int> TokenSeries::distinguished() const {
  std::vector<int> out{from_};
  for (std::size_t i = 0; i < different_.size(); ++i)
    if (different_[i]) out.push_back(from_ - 1 - int(i));
  return out;
}

}  // namespace ms
