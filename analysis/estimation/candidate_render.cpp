#include "analysis/estimation/candidate_render.hpp"

#include <cmath>
#include <numbers>

#include "synthesis/damping_law.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/resonator_bank.hpp"

namespace ms {

namespace {
// The set is resolved with this E/rho and no damping, so its modes' (2 pi f)^2 / kProbeModulus are the
// eigenvalues for E/rho = 1. Below every material's E/rho so that the set's Nyquist truncation keeps
// every mode any real material can sound (the object's max_modes still bounds the count).
constexpr double kProbeModulus = 1e4;
}  // namespace

ObjectEigen object_eigen_from_paramset(const std::string& path) {
  const ParamSet set = load_paramset(
      path, {"damping.law=rayleigh", "damping.alpha1=0", "damping.alpha2=0",
             "specific_modulus_m2_s2=" + std::to_string(kProbeModulus), "amp_scale=1"});
  ObjectEigen out;
  out.strike = set.excitation;
  for (const Mode& m : set.model.modes) {
    const double omega = 2.0 * std::numbers::pi * m.freq_hz;
    out.lambda0.push_back(omega * omega / kProbeModulus);
    out.gain.push_back(std::cos(m.phase_rad) < 0 ? -m.amp : m.amp);
  }
  return out;
}

ModalModel candidate_model(const ObjectEigen& object, const Candidate& c, double nyquist_hz) {
  const DampingLaw law{DampingKind::rayleigh, c.alpha, c.beta, 1.0, 0.0};
  ModalModel model = modes_from_eigenvalues(object.lambda0, law, c.gamma, c.sigma, object.gain, nullptr);
  drop_modes_at_or_above(model, nyquist_hz);
  return model;
}

std::vector<float> render_candidate(const ModalModel& model, const Excitation& excitation, double sample_rate_hz,
                                    std::size_t frames) {
  return render_bank(model, excitation, sample_rate_hz, frames);
}

}  // namespace ms
