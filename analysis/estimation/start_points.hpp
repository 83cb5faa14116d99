// Starting points of the material estimation (patent US 9,401,684 Sec. 5.3): every pair of dominant
// reference modes fixes a Rayleigh circle (alpha, beta) through both, Eq. 8 (when no pair has a physical
// circle, the nearest physical ones); every eigenvalue of the
// virtual object's Pareto set (no other has a smaller eigenvalue and a larger excitation) is then
// mapped onto the most dominant reference mode, which fixes gamma/gamma0 (its frequency) and sigma
// (its amplitude). The estimation starts a local search from each and keeps the best.
// Rayleigh damping in Ren's form: d = (alpha + beta lambda) / 2, f = sqrt(lambda - d^2) / 2pi, i.e.
// DampingLaw{rayleigh, alpha1 = alpha, alpha2 = beta} (synthesis/damping_law.hpp).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "synthesis/modal_model.hpp"

namespace ms {

struct RayleighCircle {
  double alpha = 0.0;  // 1/s
  double beta = 0.0;   // s
};

// The (alpha, beta) whose circle passes through both modes: with lambda_i = (2 pi f_i)^2 + d_i^2,
// 2 d_i = alpha + beta lambda_i. Nothing when the eigenvalues coincide or alpha or beta would be
// negative (no physical material damps that way).
std::optional<RayleighCircle> rayleigh_circle_through(const Mode& a, const Mode& b);

// The circle through both modes when it is physical; otherwise the least-squares line through them
// with the negative coefficient held at 0 (alpha 0 when the decays fit only a negative alpha, beta 0
// when the upper mode decays slower). Noise on two decays easily tips the exact circle negative
// where the material's alpha or beta is small; the search then starts from the nearest material.
RayleighCircle nearest_physical_circle(const Mode& a, const Mode& b);

// The eigenvalue lambda [(rad/s)^2] that this circle maps to a mode of freq_hz: the smaller root of
// lambda - ((alpha + beta lambda)/2)^2 = (2 pi f)^2 (the underdamped branch); nothing when the circle
// does not reach that frequency.
std::optional<double> eigenvalue_for_frequency(const RayleighCircle& c, double freq_hz);

// Indices of the pairs (lambda0_i, excitation_i) that no other pair beats with a smaller eigenvalue
// and a larger |excitation|, in ascending eigenvalue.
std::vector<std::size_t> pareto_eigenvalues(const std::vector<double>& lambda0, const std::vector<double>& excitation);

struct StartPoint {
  RayleighCircle circle;
  double stiffness_ratio = 1.0;  // gamma / gamma0: lambda = ratio * lambda0
  double amp_scale = 1.0;        // sigma: amp = sigma * |excitation|
  std::size_t mode_a = 0, mode_b = 0;  // the reference modes (indices into `modes`) fixing the circle
  std::size_t eigenvalue = 0;          // the eigenvalue (index into lambda0) mapped onto the dominant mode
};

// Which eigenvalues the most dominant mode is mapped onto: the Pareto set (the patent), or every
// eigenvalue with a non-zero excitation (equal eigenvalues once). The loudest mode of a recording
// need not lie on the excitation's Pareto set: the ear's weighting and the damping reorder the modes
// (a bar struck near its end excites its fundamental most, yet a plastic bar's loudest mode is its
// fifth), and then no Pareto start has the right gamma. `every` stops at the 3k + 8 lowest, k the
// dominant mode's rank in frequency among `modes`.
enum class StartEigenvalues { pareto, every };

// All starting points from the `dominant` reference modes of largest weight (weights: one per mode,
// e.g. the loudness weights of perceptual_metric.hpp) and the object's eigenvalues lambda0 with their
// excitations for the struck point. The most dominant mode is the one of largest weight.
std::vector<StartPoint> start_points(const std::vector<Mode>& modes, const std::vector<double>& weights,
                                     const std::vector<double>& lambda0, const std::vector<double>& excitation,
                                     std::size_t dominant = 5, StartEigenvalues onto = StartEigenvalues::pareto);

// How well gamma lines the object's eigenvalues up with the recording's modes, whatever the damping:
// the weighted share (weights: one per mode) of the modes whose eigenvalue (2 pi f)^2 + d^2 lies within
// a relative rel_tol of some gamma lambda0_e. The true gamma lines up every mode the extractor found
// cleanly, a wrong one only those a dense spectrum happens to hold, so that it tells the eigenvalue the
// dominant mode belongs to where the dominant mode alone cannot. 0 when no mode weighs anything.
double eigenvalue_alignment(const std::vector<Mode>& modes, const std::vector<double>& weights,
                            const std::vector<double>& lambda0, double gamma, double rel_tol = 4e-3);

}  // namespace ms
