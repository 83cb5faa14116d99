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
  // The gamma candidates (eigenvalues the dominant mode is mapped onto) are ranked by how many of the
  // recording's modes they line up with the object's eigenvalues; the best max_starts are kept, each
  // with the best of its circles (imaged_per_gamma of them, the best by the feature metric alone,
  // scored by the whole metric), screened by a short search of screen_evaluations; the best
  // refined_starts screened ones are searched on up to max_evaluations in all.
  std::size_t imaged_per_gamma = 4;
  std::size_t max_starts = 6;
  std::size_t screen_evaluations = 60;
  std::size_t refined_starts = 2;
  std::size_t max_evaluations = 250;  // per refined start, the screening's included
  // The hybrid metric's minimum is then polished by Pi_psycho alone inside a small box round it
  // (alpha, beta, sigma and the contact within a factor 1.5, gamma within 2 %): the feature points
  // are the extractor's, whose decays of close or weak modes run fast (an unresolved pair's beating
  // reads as decay), and their match pulls beta up by 20-70 % on plates where the image itself is
  // lowest at the truth. The hybrid finds the basin (gamma, the circle); the image settles in it.
  // 0: no polish (the hybrid's minimum is the estimate).
  std::size_t polish_evaluations = 120;
  double max_duration_s = 2.0;           // the recording's image is compared over at most this long
  // The strike's contact duration is searched as a fifth parameter (its shape is the excitation's):
  // a longer contact low-passes the upper modes, which a fixed duration would read as a smaller sigma
  // or a faster decay. Ignored for an impulse.
  bool fit_contact = true;
  double min_contact_s = 2e-5, max_contact_s = 5e-3;
  // Each candidate may be rendered with only the modes the masking rule (synthesis/masking_pruning.hpp)
  // hears (its feature points keep every mode): 10 dB above the metric's playback level and a_v =
  // 30 dB. Off by default: the patent's loudness image knows no masking, so a masked mode left out is
  // a band of the image changed, and on Ren's porcelain bar (noise-free, impulse) that moves alpha to
  // 0.50 of the truth. The render floor below is the pruning that changes no cell of the image.
  bool prune_inaudible = false;
  // The recording's white-noise standard deviation (ExtractedFeatures::noise_sigma). Each candidate is
  // compared with this much noise added (one seeded draw for all), as the recording has it: after a
  // fast decay the recording's image is noise for most of its length, and a noise-free candidate
  // would then be rewarded for filling it with extra, slower or lower modes.
  double noise_sigma = 0.0;
  // The noise is added to each candidate by its expected power in every band of the image
  // (PerceptualReference::compare with noise_sigma) rather than as one seeded draw: one draw is
  // one particular waveform, and where a weak mode meets the noise the search then fits that draw's
  // loudness against the recording's (a bias in beta of 10-30 % on plates of fast upper modes).
  bool noise_by_expected_power = true;
  double prune_threshold_db = 30.0;  // a_v of the masking rule
  double prune_headroom_db = 10.0;   // the rule's playback level above perceptual.playback_db_spl
  // Each candidate mode is rendered only while its envelope can stay above a floor
  // (render_candidate_above): the larger of an amplitude this far below the lowest threshold in quiet
  // of ISO 226 at the reference's calibration, and this far below the added noise's sigma. What is
  // cut changes no loudness cell measurably; a plate's fast upper modes then cost a few ms of render
  // instead of the whole recording's length. A negative margin renders every mode in full.
  double render_floor_below_quiet_db = 30.0;
  double render_floor_below_noise_db = 60.0;
};

struct StartResult {
  StartPoint start;
  Candidate initial, fitted;
  double contact_s = 0.0;  // the fitted contact duration (the excitation's when not fitted)
  PerceptualScores scores;  // of the fitted candidate
  std::size_t iterations = 0, evaluations = 0;
};

struct MaterialEstimate {
  Candidate material;
  double contact_s = 0.0;  // the strike's contact duration the estimate was rendered with (fitted or given)
  PerceptualScores scores;
  std::vector<StartResult> starts;  // every local search, in the order run
  Candidate hybrid_minimum;         // the lowest Pi_hybrid found, before the polish
  std::size_t polish_evaluations = 0;
  std::size_t iterations = 0;       // summed over the starts
  std::size_t matched_modes = 0;    // recording modes with a positive match score against the estimate
  std::size_t frames = 0;           // samples of the recording compared (from its onset)
};

// recording: mono samples from the onset; modes: its extracted modes (amplitudes at the onset).
// Throws std::invalid_argument when no start point exists (fewer than 2 usable modes).
MaterialEstimate estimate_material(const std::vector<float>& recording, double sample_rate_hz,
                                   const std::vector<Mode>& modes, const ObjectEigen& object,
                                   const Excitation& excitation, const EstimateOptions& options = {});

// One candidate's scores exactly as estimate_material computes them for this recording (same compared
// length, added noise and pruning), the strike's duration contact_s: e.g. the truth's, to tell a
// search that stopped short from a metric whose minimum lies elsewhere.
PerceptualScores score_candidate(const std::vector<float>& recording, double sample_rate_hz,
                                 const std::vector<Mode>& modes, const ObjectEigen& object, const Excitation& excitation,
                                 const Candidate& candidate, double contact_s, const EstimateOptions& options = {});

}  // namespace ms
