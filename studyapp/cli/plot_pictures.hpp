// Pictures drawn by more than one subcommand: the fitted damping laws as curves, a pruned model's
// masking picture, loudness images as the plots take them.
#pragma once
#include <string>
#include <vector>

#include "analysis/damping/damping_features.hpp"
#include "analysis/estimation/loudness_image.hpp"
#include "synthesis/damping_law.hpp"
#include "synthesis/masking_pruning.hpp"
#include "synthesis/modal_model.hpp"
#include "studyapp/plots/plots.hpp"

namespace ms::cli {

// The law's c(lambda) [1/s] sampled log-uniformly over [lo, hi] (n points), for drawing.
std::vector<plots::XY> sample_law(const DampingLaw& law, double lo, double hi, int n = 200);

// img as image[band][frame] over `frames` frames (missing frames 0), the layout plots::loudness_image takes.
std::vector<std::vector<double>> by_band(const BarkImage& img, std::size_t frames);

// lsq, lb and emg fits of one law to the points, as curves over the data's lambda range, each named
// by its estimator and coefficients.
std::vector<plots::Series> fitted_curves(const std::vector<DampingPoint>& points, DampingKind law);

// Mode levels (kept / dropped), masking threshold and threshold in quiet of a pruning result.
void plot_masking_model(const ModalModel& model, const PruneResult& r, const std::string& output,
                        const std::string& title);

}  // namespace ms::cli
