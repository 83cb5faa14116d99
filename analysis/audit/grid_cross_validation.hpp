// Leave-one-strike-out cross-validation of a grid search, from the per-strike gaps of every candidate:
// for each strike, the candidate best on the others is scored on it. A fit's grid, evaluated on all
// strikes once, is then also an honest comparison between two families of extension.
#pragma once
#include <vector>

namespace ms::audit {

// table[c][s]: gap of candidate c on strike s. Mean held-out gap over the strikes (a single strike: its
// best in-sample gap; an empty table: 0).
double leave_one_out_gap(const std::vector<std::vector<double>>& table);

}  // namespace ms::audit
