#include "analysis/audit/augmented_paramset.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/audit/effect_catalog.hpp"
#include "analysis/audit/room_power.hpp"
#include "synthesis/paramset_recipe.hpp"
#include "synthesis/resonator_bank.hpp"

namespace ms::audit {

namespace {

// SNR over the whole sound, as effects.noise defines it: the rendered modes plus the tail and the
// burst, which are part of the signal effects.noise is relative to.
double noise_snr_db(const AuditData& data, const AuditModel& model, const ParamSetRecipe& recipe, std::size_t strike) {
  ModalModel rendered;
  const std::vector<double>& extra = recipe.support_damping ? recipe.support_damping->per_mode_decay_per_s
                                                            : std::vector<double>(recipe.modes.size(), 0.0);
  for (std::size_t i = 0; i < recipe.modes.size(); ++i) {
    rendered.modes.push_back(recipe.modes[i]);
    rendered.modes.back().decay_per_s += extra[i];
  }
  const std::vector<float> x =
      render_bank(rendered, recipe.excitation, recipe.sample_rate_hz, data.measured.strikes[strike].samples.size());
  double power = 0.0;
  for (float v : x) power += double(v) * double(v);
  power /= double(std::max<std::size_t>(x.size(), 1));
  if (recipe.room.enabled) power *= 1.0 + std::pow(10.0, -recipe.room.drr_db / 10.0);
  if (recipe.reverb.enabled) power *= 1.0 + std::pow(10.0, recipe.reverb.level_db / 10.0);
  if (recipe.transient.enabled) power *= 1.0 + std::pow(10.0, recipe.transient.level_db / 10.0);
  const double sigma = noise_white_sigma(data, model);
  return std::clamp(10.0 * std::log10(power / std::max(sigma * sigma, 1e-30)), -20.0, 200.0);
}

}  // namespace

std::size_t representative_strike(const AuditModel& model) {
  return std::size_t(std::max_element(model.gain.begin(), model.gain.end()) - model.gain.begin());
}

ParamSetRecipe augmented_recipe(const AuditData& data, const AuditModel& model, const std::string& description) {
  const std::size_t s = representative_strike(model);
  ParamSetRecipe recipe;
  recipe.description = description;
  recipe.sample_rate_hz = data.measured.sample_rate_hz;
  recipe.duration_s = double(data.measured.strikes[s].samples.size()) / recipe.sample_rate_hz;
  // Modes at this strike's gain, material decay; the support excess goes to effects.support_damping.
  const bool support = !model.extra_decay_per_s.empty();
  // In a room the modes are the dry ones the room is applied to (room_power.hpp).
  const RoomRates rates = model.room.enabled ? room_rates(model.room, recipe.sample_rate_hz) : RoomRates{};
  std::vector<double> extra;
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    const AuditMode& m = model.modes[n];
    if (m.freq_hz >= 0.5 * recipe.sample_rate_hz) continue;
    double amp = m.amp * model.gain[s] * std::exp(model.hit.log_factor(s, n));  // contact: excitation
    const double e = support ? model.extra_decay_per_s[s][n] : 0.0;
    if (model.room.enabled)
      amp *= m.room_gain *
             std::sqrt(dry_power_scale(rates, room_octave_band(m.freq_hz), (m.decay_per_s + e) / recipe.sample_rate_hz));
    auto emit = [&](double f, double a) {
      recipe.modes.push_back({f, m.decay_per_s, a, m.phase_rad});  // its onset phase: the beats come out as measured
      extra.push_back(e);
    };
    if (const Doublets& db = m.doublet; db.split_hz > 0.0) {
      const double norm = std::hypot(1.0 - db.balance, db.balance);
      emit(m.freq_hz - 0.5 * db.split_hz, amp * (1.0 - db.balance) / norm);
      emit(m.freq_hz + 0.5 * db.split_hz, amp * db.balance / norm);
    } else {
      emit(m.freq_hz, amp);
    }
  }
  if (support) recipe.support_damping = SupportDamping{.per_mode_decay_per_s = extra};
  if (const double tau = model.contact_s.empty() ? 0.0 : model.contact_s[s]; tau > 0.0)
    recipe.excitation = {.shape = model.contact_shape, .contact_s = tau};
  // Distinct seeds: noises drawn from one seed would be the same sequence, correlated, and add 3 dB too much.
  recipe.room = model.room;
  recipe.room.seed = 4;
  recipe.reverb = model.reverb;
  recipe.reverb.seed = 2;
  recipe.transient = model.transient;
  recipe.transient.seed = 3;
  if (!model.noise_band_variance.empty())
    recipe.noise = {.snr_db = noise_snr_db(data, model, recipe, s), .seed = 1, .enabled = true};
  recipe.level = {.mode = LevelMode::none};
  recipe.format = SampleFormat::float32;
  return recipe;
}

std::string augmented_paramset_yaml(const AuditData& data, const AuditModel& model, const std::string& description) {
  return write_yaml(augmented_recipe(data, model, description));
}

}  // namespace ms::audit
