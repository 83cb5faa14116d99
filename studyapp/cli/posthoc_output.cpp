#include "studyapp/cli/posthoc_output.hpp"

#include <cstdio>

#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

nlohmann::json posthoc_json(const Posthoc& h) {
  nlohmann::json pairs = nlohmann::json::array();
  for (const auto& c : h.pairs)
    pairs.push_back({{"a", c.level_a}, {"b", c.level_b}, {"mean_diff", c.mean_diff}, {"t", num_json(c.t)},
                     {"df", c.df}, {"p", num_json(c.p)}, {"p_adjusted", num_json(c.p_adjusted)}});
  return {{"factor", h.factor}, {"within", h.within}, {"adjust", p_adjust_name(h.method)}, {"pairs", pairs}};
}

void print_posthoc(const Posthoc& h) {
  std::printf("\nPairwise %s t-tests of %s (%s adjustment over %zu pairs%s)\n", h.within ? "paired" : "pooled-SD",
              h.factor.c_str(), p_adjust_name(h.method), h.pairs.size(),
              h.within ? "; subjects' marginal means" : "; one mean per subject");
  std::printf("%-16s %-16s %10s %8s %5s %8s %8s\n", "a", "b", "a - b", "t", "df", "p", "p adj");
  for (const auto& c : h.pairs)
    std::printf("%-16s %-16s %10.4g %8.4g %5.0f %8s %8s\n", c.level_a.c_str(), c.level_b.c_str(), c.mean_diff, c.t,
                c.df, fmt_p(c.p).c_str(), fmt_p(c.p_adjusted).c_str());
}

}  // namespace ms::cli
