#include "analysis/estimation/candidate_render.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
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

namespace {

// 8-point Gauss-Legendre nodes and weights on [0, 1].
constexpr std::array<double, 8> kNode = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
                                         0.4082826787521751, 0.5917173212478249, 0.7627662049581645,
                                         0.8983332387068134, 0.9801449282487681};
constexpr std::array<double, 8> kWeight = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
                                           0.1813418916891810, 0.1813418916891810, 0.1568533229389436,
                                           0.1111905172266872, 0.0506142681451881};

// The contact, sampled once for every mode: the force at the Gauss nodes of each sample interval
// [(n-1)T, nT] inside it (n = 1 .. frames-1) and of the last piece [(frames-1)T, tau].
struct ContactSamples {
  std::size_t frames = 0;  // samples 0 .. frames-1 lie inside the contact
  std::vector<std::array<double, 8>> force;  // per interval, times its Gauss weights and length
  std::array<double, 8> tail_force{}, tail_offset_s{};
  ContactSamples(const Excitation& e, double sample_rate_hz) {
    if (e.shape == PulseShape::impulse || e.contact_s <= 0.0) return;
    const double T = 1.0 / sample_rate_hz;
    frames = std::size_t(std::floor(e.contact_s * sample_rate_hz)) + 1;
    force.resize(frames);
    for (std::size_t n = 1; n < frames; ++n)
      for (std::size_t q = 0; q < 8; ++q) force[n][q] = kWeight[q] * T * e.force((double(n - 1) + kNode[q]) * T);
    const double start = double(frames - 1) * T, piece = e.contact_s - start;
    for (std::size_t q = 0; q < 8; ++q) {
      tail_offset_s[q] = kNode[q] * piece;
      tail_force[q] = kWeight[q] * piece * e.force(start + tail_offset_s[q]);
    }
  }
};

}  // namespace

std::vector<float> render_candidate_above(const ModalModel& model, const Excitation& excitation, double sample_rate_hz,
                                          std::size_t frames, double floor_amp) {
  if (!(floor_amp > 0.0)) return render_candidate(model, excitation, sample_rate_hz, frames);
  const double T = 1.0 / sample_rate_hz;
  const ContactSamples contact(excitation, sample_rate_hz);
  std::vector<double> head(std::min(contact.frames, frames), 0.0);
  // Bank lengths: 1/64, 1/16, 1/4 and all of the frames.
  constexpr std::array<std::size_t, 4> kDivisor = {64, 16, 4, 1};
  std::array<ModalModel, kDivisor.size()> banks;
  for (const Mode& m : model.modes) {
    const std::complex<double> p(-m.decay_per_s, 2.0 * std::numbers::pi * m.freq_hz);
    const std::complex<double> g = excitation.gain * std::polar(m.amp, m.phase_rad);
    // After the contact the mode is Im(g G e^{p t}), G = int_0^tau F(s) e^{-p s} ds; during it,
    // Im(g e^{p t} int_0^t F(s) e^{-p s} ds), summed exactly into the head.
    std::complex<double> G = 1.0;
    if (contact.frames > 0) {
      std::array<std::complex<double>, 8> node;  // e^{-p x_q T}
      for (std::size_t q = 0; q < 8; ++q) node[q] = std::exp(-p * (kNode[q] * T));
      const std::complex<double> pole = std::exp(p * T);
      std::complex<double> integral = 0.0, back = 1.0, forward = 1.0;  // back e^{-p (n-1) T}, forward e^{p n T}
      for (std::size_t n = 0; n < contact.frames; ++n) {
        if (n > 0) {
          std::complex<double> piece = 0.0;
          for (std::size_t q = 0; q < 8; ++q) piece += contact.force[n][q] * node[q];
          integral += piece * back;
          back /= pole;
        }
        if (n < head.size()) head[n] += std::imag(g * forward * integral);
        forward *= pole;
      }
      const std::complex<double> start = std::exp(-p * (double(contact.frames - 1) * T));
      for (std::size_t q = 0; q < 8; ++q) integral += contact.tail_force[q] * start * std::exp(-p * contact.tail_offset_s[q]);
      G = integral;
    }
    const std::complex<double> after = g * G;  // the free decay's complex amplitude at t = 0
    const double peak = std::abs(after);
    if (!(peak > floor_amp)) continue;
    const double end_frames = m.decay_per_s > 0.0 ? std::ceil(std::log(peak / floor_amp) / m.decay_per_s * sample_rate_hz) + 1.0
                                                  : HUGE_VAL;
    std::size_t b = 0;
    while (b + 1 < kDivisor.size() && double(frames / kDivisor[b]) < std::max(end_frames, double(head.size()))) ++b;
    banks[b].modes.push_back({m.freq_hz, m.decay_per_s, std::abs(after), std::arg(after)});
  }
  std::vector<float> y(frames, 0.0f);
  const Excitation impulse;  // the free decays from t = 0; the contact's samples are the head's
  for (std::size_t b = 0; b < banks.size(); ++b) {
    if (banks[b].modes.empty()) continue;
    const std::size_t n = frames / kDivisor[b];
    const std::vector<float> part = render_bank(banks[b], impulse, sample_rate_hz, n);
    for (std::size_t i = 0; i < n; ++i) y[i] += part[i];
  }
  for (std::size_t i = 0; i < head.size(); ++i) y[i] = float(head[i]);
  return y;
}

}  // namespace ms
