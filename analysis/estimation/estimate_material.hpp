// Estimation of a material {alpha, beta, gamma, sigma} from one recorded impact and the struck
// object's geometry (patent US 9,401,684 Sec. 5.3): start points from the recording's dominant modes
// (start_points.hpp), a bounded Nelder-Mead search in log parameters from the best of them minimising
// Pi_hybrid (perceptual_metric.hpp) between the recording and the candidate's render, the lowest kept.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/estimation/candidate_render.hpp"
#include "analysis/estimation/perceptual_metric.hpp"
#include "analysis/estimation/start_points.hpp"

namespace ms {

struct EstimateOptions {
  PerceptualOptions perceptual;
  std::size_t dominant_modes = 5;        // reference modes the start points are built from
  StartEigenvalues start_eigenvalues = StartEigenvalues::every;  // what the dominant mode is mapped onto
  std::size_t max_starts = 6;            // local searches run, from the start points of lowest metric
  std::size_t max_evaluations = 250;     // per local search
  double max_duration_s = 2.0;           // the recording's image is compared over at most this long
};

struct StartResult {
  StartPoint start;
  Candidate initial, fitted;
  PerceptualScores scores;  // of the fitted candidate
  std::size_t iterations = 0, evaluations = 0;
};

struct MaterialEstimate {
  Candidate material;
  PerceptualScores scores;
  std::vector<StartResult> starts;  // every local search, in the order run
  std::size_t iterations = 0;       // summed over the starts
  std::size_t matched_modes = 0;    // recording modes with a positive match score against the estimate
  std::size_t frames = 0;           // samples of the recording compared (from its onset)
};

// recording: mono samples from the onset; modes: its extracted modes (amplitudes at the onset).
// Throws std::invalid_argument when no start point exists (fewer than 2 usable modes).
MaterialEstimate estimate_material(const std::vector<float>& recording, double sample_rate_hz,
                                   const std::vector<Mode>& modes, const ObjectEigen& object,
                                   const Excitation& excitation, const EstimateOptions& options = {});

}  // namespace ms
