// mushra_boxes: mushra_analyse for the kept assessors and the statistics, the ratings filtered by it.
#include "studyapp/core/mushra_boxes.hpp"

#include <cmath>
#include <limits>
#include <set>

namespace ms {

MushraBoxes mushra_boxes(const std::vector<MushraRating>& ratings, const MushraOptions& options) {
  const MushraResult res = mushra_analyse(ratings, options);
  std::set<std::string> kept;
  for (const auto& a : res.assessors)
    if (!a.excluded) kept.insert(a.subject);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  MushraBoxes out;
  out.assessors = res.assessors.size();
  out.kept = res.included;
  for (const auto& c : res.conditions) {
    out.conditions.push_back(c.condition);
    out.ratings.emplace_back();
    for (const auto& r : ratings)
      if (r.condition == c.condition && kept.count(r.subject)) out.ratings.back().push_back(r.rating);
    out.means.push_back(c.n ? c.mean : nan);
    out.ci_low.push_back(c.ci_low.value_or(nan));
    out.ci_high.push_back(c.ci_high.value_or(nan));
  }
  return out;
}

std::string reference_from_anchor_names(const std::vector<std::string>& conditions) {
  for (const std::string& c : conditions)
    if (const auto at = c.rfind("~lp"); at != std::string::npos && at > 0) return c.substr(0, at);
  return "";
}

}  // namespace ms
