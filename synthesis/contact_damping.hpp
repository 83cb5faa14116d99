// Support damping from contacts (Zheng & James 2011, as Sterling et al. 2019 apply it, Eq 1.16):
//   G = sum_k c_k Phi_k^T (mu I + (1 - mu) n_k n_k^T) Phi_k,
// Phi_k the 3 x modes block of the eigenvector matrix at contact point k (each mode's displacement
// vector there), n_k the contact normal, mu the friction coefficient, c_k the contact's strength.
// The paper keeps only the diagonal ("each damping model may be augmented by adding the corresponding
// diagonal component of G"): mode i gains
//   G_ii = sum_k c_k (mu |phi_ki|^2 + (1 - mu) (n_k . phi_ki)^2).
//
// What our objects make of it: the free bar (Euler-Bernoulli) and the free plate (Kirchhoff) have one
// displacement, transverse, phi_ki = w_i(x_k) e_z with w_i the mass-normalised shape (mean w^2 = 1).
// With theta_k the angle between the contact normal and e_z, (n_k . phi_ki)^2 = w^2 cos^2 theta_k, so
//   G_ii = sum_k c_k w_i(x_k)^2 (mu + (1 - mu) cos^2 theta_k).
// A support under a face (theta = 0: the normal along the displacement) adds c_k w^2 whatever mu is;
// mu matters only for a contact whose normal leans away from the displacement (theta = 90 deg: a
// contact on the bar's end or the plate's rim, rubbing along the motion, adds mu c_k w^2). In-plane
// motion, which these models do not have, is left out. c_k is in 1/s (G is a damping coefficient in
// the damping laws' units, c = 2d, damping_law.hpp), so the mode's decay rate d gains G_ii / 2.
// The coupling G's off-diagonal terms would bring is left out, as in the paper.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

namespace ms {

struct SupportContact {
  double position = 0.0;              // bar: fraction of the length; plate: of the radius, on the hits' ray
  std::optional<double> c_per_s = {};  // its own c_k (else the support's c)
  double normal_deg = 0.0;             // angle between the contact normal and the displacement, [0, 90]
};

// The decay each mode gains, G_ii / 2 [1/s]. shapes[k][i] is mode i's displacement w_i at contact k,
// c_per_s[k] contact k's c_k; normal_deg[k] its theta_k.
std::vector<double> contact_decay_per_s(const std::vector<std::vector<double>>& shapes,
                                        const std::vector<double>& c_per_s, const std::vector<double>& normal_deg,
                                        double mu, std::size_t modes);

}  // namespace ms
