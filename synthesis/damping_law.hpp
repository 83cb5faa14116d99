// Damping laws: how a mode's decay follows from its eigenvalue lambda = omega^2 [(rad/s)^2].
// Sterling's convention c = 2d (d = amplitude decay rate, 1/s):
//   rayleigh   c = alpha1 + alpha2 * lambda                 (Ren: d = (alpha + beta lambda)/2)
//   powerlaw   c = alpha2 * omega^(2 alpha3)
//   hybrid     c = alpha1 + alpha2 * omega^(2 alpha3)        (alpha3 = 1 is Rayleigh)
//   constant_q d = 2 pi f D = D * omega                      (D ~ 2e-4 metal ... 0.05 plastic)
//   relaxation d = alpha1/2 + omega (D + S x / (1 + x^2)),   x = f / relaxation_hz
//              a constant loss plus one Debye (Zener) relaxation peak of height S/2 at relaxation_hz, the
//              shape of thermoelastic damping; no fitted law (Rayleigh, power, hybrid) contains it, which
//              is what the replications' stand-ins for recordings use it for
// Eigenvalues are physical, lambda = omega^2 in (rad/s)^2, not normalised: with this choice
// Sterling's table reproduces the paper's worked example (porcelain, 10 kHz: d = 20 hybrid, 12 Rayleigh).
#pragma once
#include <string>
#include <vector>

#include "synthesis/modal_model.hpp"
#include "synthesis/name_table.hpp"

namespace ms {

enum class DampingKind { rayleigh, powerlaw, hybrid, constant_q, relaxation };
inline constexpr NameTable<DampingKind, 5> kDampingKindNames{{{DampingKind::rayleigh, "rayleigh"},
                                                               {DampingKind::powerlaw, "powerlaw"},
                                                               {DampingKind::hybrid, "hybrid"},
                                                               {DampingKind::constant_q, "constant_q"},
                                                               {DampingKind::relaxation, "relaxation"}}};

struct DampingLaw {
  DampingKind kind = DampingKind::rayleigh;
  double alpha1 = 0.0;  // 1/s
  double alpha2 = 0.0;  // s for Rayleigh; s^(2 alpha3 - 1) otherwise
  double alpha3 = 1.0;  // exponent (powerlaw, hybrid)
  double loss_factor = 0.0;  // D of the constant-Q and relaxation laws
  double relaxation_strength = 0.0;  // S of the relaxation law (its peak adds S/2 to D)
  double relaxation_hz = 0.0;        // where the relaxation peaks (0: no peak)

  // Amplitude decay rate d [1/s] of a mode with eigenvalue lambda [(rad/s)^2].
  double decay_per_s(double lambda) const;
};

DampingKind parse_damping_kind(const std::string& name);  // throws std::invalid_argument
std::string to_string(DampingKind kind);

// Modes from eigenvalues: lambda_i = stiffness_ratio * lambda0_i (gamma/gamma0), d_i from the law,
// f_i = sqrt(lambda_i - d_i^2) / 2pi. Overdamped modes (d_i^2 >= lambda_i) are dropped and counted
// in *overdamped. Amplitudes are |amp_scale * gains[i]| (gains may be empty: all 1), a negative
// gain giving phase pi.
ModalModel modes_from_eigenvalues(const std::vector<double>& lambda0, const DampingLaw& law,
                                  double stiffness_ratio, double amp_scale,
                                  const std::vector<double>& gains, std::size_t* overdamped);

}  // namespace ms
