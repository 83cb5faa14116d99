// Pictures `modalstudy plot` draws from more than one subcommand: the fitted damping laws as curves and
// a pruned model's masking picture.
#pragma once
#include <string>
#include <vector>

#include "analysis/damping/damping_features.hpp"
#include "synthesis/damping_law.hpp"
#include "synthesis/masking_pruning.hpp"
#include "synthesis/modal_model.hpp"
#include "studyapp/plots/plots.hpp"

namespace ms::cli {

// lsq, lb and emg fits of one law to the points, as curves over the data's lambda range, each named
// by its estimator and coefficients.
std::vector<plots::Series> fitted_curves(const std::vector<DampingPoint>& points, DampingKind law);

// Mode levels (kept / dropped), masking threshold and threshold in quiet of a pruning result.
void plot_masking_model(const ModalModel& model, const PruneResult& r, const std::string& output,
                        const std::string& title);

}  // namespace ms::cli
