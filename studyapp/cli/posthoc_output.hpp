// Post-hoc pairwise t-tests (analysis/stats/posthoc.hpp) as the stats commands print them and put
// them in their JSON.
#pragma once
#include <nlohmann/json.hpp>

#include "analysis/stats/posthoc.hpp"

namespace ms::cli {

nlohmann::json posthoc_json(const Posthoc& h);
void print_posthoc(const Posthoc& h);

}  // namespace ms::cli
