// A candidate material {alpha, beta, gamma, sigma} heard on one object (patent US 9,401,684 Eq. 12):
// lambda = gamma lambda0 (the object's eigenvalues for E/rho = 1 m^2/s^2, so gamma is E/rho itself),
// d = (alpha + beta lambda) / 2, f = sqrt(lambda - d^2) / 2 pi, a = sigma a0 (the mode shape at the
// struck point), rendered by the resonator bank (exact for a sum of damped sinusoids).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "synthesis/excitation.hpp"
#include "synthesis/modal_model.hpp"

namespace ms {

// The geometry the estimation holds fixed: eigenvalues for E/rho = 1 and signed gains at the hit point.
struct ObjectEigen {
  std::vector<double> lambda0;  // (rad/s)^2 per (m^2/s^2), ascending
  std::vector<double> gain;     // a0, one per eigenvalue
  Excitation strike;            // how the object is struck (a parameter set's excitation)
};

struct Candidate {
  double alpha = 0.0;  // 1/s
  double beta = 0.0;   // s
  double gamma = 0.0;  // E/rho [m^2/s^2]
  double sigma = 1.0;  // amplitude scale
};

// The object of a parameter set (its `object:` or `eigenvalues:` with gains, hit point, size and
// stiffness scales) and its excitation; its material and damping are replaced, so any in the file is
// ignored.
// Throws InputError like load_paramset.
ObjectEigen object_eigen_from_paramset(const std::string& path);

// The modes of the candidate below nyquist_hz; overdamped modes are dropped.
ModalModel candidate_model(const ObjectEigen& object, const Candidate& c, double nyquist_hz);

// The candidate's sound, `frames` samples from the strike.
std::vector<float> render_candidate(const ModalModel& model, const Excitation& excitation, double sample_rate_hz,
                                    std::size_t frames);

// The same sound with every mode rendered only while its envelope can exceed floor_amp (a mode never
// above it is left out): after the contact a mode's amplitude is at most |amp gain| e^{-d (t - tau)}
// (the contact's force has area 1 and is non-negative), so each sample differs from
// render_candidate's by less than floor_amp per mode left out or cut. The modes are rendered in a few
// banks of increasing length, the shortest that holds each mode's end. floor_amp 0: render_candidate.
std::vector<float> render_candidate_above(const ModalModel& model, const Excitation& excitation, double sample_rate_hz,
                                          std::size_t frames, double floor_amp);

}  // namespace ms
