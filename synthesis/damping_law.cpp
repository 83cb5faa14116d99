#include "synthesis/damping_law.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ms {

double DampingLaw::decay_per_s(double lambda) const {
  const double omega = std::sqrt(std::max(lambda, 0.0));
  switch (kind) {
    case DampingKind::rayleigh: return 0.5 * (alpha1 + alpha2 * lambda);
    case DampingKind::powerlaw: return 0.5 * alpha2 * std::pow(omega, 2.0 * alpha3);
    case DampingKind::hybrid: return 0.5 * (alpha1 + alpha2 * std::pow(omega, 2.0 * alpha3));
    case DampingKind::constant_q: return loss_factor * omega;
    case DampingKind::relaxation: {
      const double x = relaxation_hz > 0.0 ? omega / (2.0 * std::numbers::pi * relaxation_hz) : 0.0;
      return 0.5 * alpha1 + omega * (loss_factor + relaxation_strength * x / (1.0 + x * x));
    }
  }
  return 0.0;
}

DampingKind parse_damping_kind(const std::string& name) {
  if (const auto kind = find_enum(kDampingKindNames, name)) return *kind;
  throw std::invalid_argument(unknown_name_problem("damping law", name, kDampingKindNames));
}

std::string to_string(DampingKind kind) { return std::string(enum_name(kDampingKindNames, kind)); }

ModalModel modes_from_eigenvalues(const std::vector<double>& lambda0, const DampingLaw& law,
                                  double stiffness_ratio, double amp_scale,
                                  const std::vector<double>& gains, std::size_t* overdamped) {
  ModalModel model;
  std::size_t dropped = 0;
  for (std::size_t i = 0; i < lambda0.size(); ++i) {
    const double lambda = stiffness_ratio * lambda0[i];
    const double d = law.decay_per_s(lambda);
    const double omega_d_sq = lambda - d * d;
    if (!(omega_d_sq > 0.0)) {
      ++dropped;
      continue;
    }
    Mode m;
    m.freq_hz = std::sqrt(omega_d_sq) / (2.0 * std::numbers::pi);
    m.decay_per_s = d;
    // A negative mode-shape value is a phase inversion: keep amp >= 0 and carry the sign as phase pi.
    const double a = amp_scale * (i < gains.size() ? gains[i] : 1.0);
    m.amp = std::abs(a);
    m.phase_rad = a < 0 ? std::numbers::pi : 0.0;
    model.modes.push_back(m);
  }
  if (overdamped) *overdamped = dropped;
  return model;
}

}  // namespace ms
