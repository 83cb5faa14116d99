#include "analysis/audit/augmented_paramset.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/audit/effect_catalog.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/resonator_bank.hpp"

namespace ms::audit {

std::size_t representative_strike(const AuditModel& model) {
  return std::size_t(std::max_element(model.gain.begin(), model.gain.end()) - model.gain.begin());
}

std::string augmented_paramset_yaml(const AuditData& data, const AuditModel& model, const std::string& description) {
  const std::size_t s = representative_strike(model);
  const double fs = data.measured.sample_rate_hz;
  const double duration_s = double(data.measured.strikes[s].samples.size()) / fs;
  std::string y;
  char buf[512];
  auto add = [&](const char* fmt, auto... v) {
    std::snprintf(buf, sizeof buf, fmt, v...);
    y += buf;
  };
  std::string quoted = description;
  std::replace(quoted.begin(), quoted.end(), '"', '\'');
  add("description: \"%s\"\n", quoted.c_str());
  add("sample_rate: %.0f\nduration_s: %.6g\nmodes:\n", fs, duration_s);
  // Modes at this strike's gain, material decay; the support excess goes to effects.support_damping.
  ModalModel rendered;
  std::vector<double> extra;
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    const AuditMode& m = model.modes[n];
    if (m.freq_hz >= 0.5 * fs) continue;
    const double amp = m.amp * model.gain[s];
    const double e = model.extra_decay_per_s.empty() ? 0.0 : model.extra_decay_per_s[s][n];
    auto emit = [&](double f, double a) {
      add("  - {freq_hz: %.10g, decay_per_s: %.8g, amp: %.8g}\n", f, m.decay_per_s, a);
      extra.push_back(e);
      rendered.modes.push_back({f, m.decay_per_s + e, a, 0.0});
    };
    if (m.split_hz > 0.0) {
      const double norm = std::hypot(1.0 - m.balance, m.balance);
      emit(m.freq_hz - 0.5 * m.split_hz, amp * (1.0 - m.balance) / norm);
      emit(m.freq_hz + 0.5 * m.split_hz, amp * m.balance / norm);
    } else {
      emit(m.freq_hz, amp);
    }
  }
  Excitation e;
  const double tau = model.contact_s.empty() ? 0.0 : model.contact_s[s];
  if (tau > 0.0) {
    e.shape = PulseShape::raised_cosine;
    e.contact_s = tau;
    add("excitation: {type: raised_cosine, contact_s: %.6g}\n", tau);
  } else {
    add("excitation: {type: impulse}\n");
  }
  const bool support = !model.extra_decay_per_s.empty(), noise = !model.noise_band_variance.empty();
  const bool reverb = model.reverb_rt60_s > 0.0, transient = model.transient_ms > 0.0;
  if (support || noise || reverb || transient) add("effects:\n");
  if (support) {
    y += "  support_damping:\n    per_mode_decay_per_s: [";
    for (std::size_t i = 0; i < extra.size(); ++i) add("%s%.6g", i ? ", " : "", extra[i]);
    y += "]\n";
  }
  if (noise) {
    // SNR over the whole sound, as effects.noise defines it.
    const std::vector<float> x = render_bank(rendered, e, fs, data.measured.strikes[s].samples.size());
    double power = 0.0;
    for (float v : x) power += double(v) * double(v);
    power /= double(std::max<std::size_t>(x.size(), 1));
    // The tail and the burst are part of the signal effects.noise is relative to.
    if (reverb) power *= 1.0 + std::pow(10.0, model.reverb_level_db / 10.0);
    if (transient) power *= 1.0 + std::pow(10.0, model.transient_level_db / 10.0);
    const double sigma = noise_white_sigma(data, model);
    const double snr = std::clamp(10.0 * std::log10(power / std::max(sigma * sigma, 1e-30)), -20.0, 200.0);
    add("  noise: {snr_db: %.4g, seed: 1}\n", snr);
  }
  // Three seeds: noises drawn from one seed would be the same sequence, correlated, and add 3 dB too much.
  if (reverb) add("  reverb: {rt60_s: %.6g, level_db: %.6g, seed: 2}\n", model.reverb_rt60_s, model.reverb_level_db);
  if (transient)
    add("  transient: {level_db: %.6g, duration_ms: %.6g, seed: 3}\n", model.transient_level_db, model.transient_ms);
  y += "level: {normalize: none}\noutput: {format: float32}\n";
  return y;
}

}  // namespace ms::audit
