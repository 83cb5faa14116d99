// reverberation: a room tail common to all bands that decays at its own rate, not the modes'. Detector:
// adding a white tail (60 dB decay time and energy relative to the direct sound fitted over all
// strikes) lowers the gap by enough. Extension: the same two numbers fitted on the training strikes;
// the tail follows each strike's direct sound (a room answers every strike alike).
#include <cmath>
#include <cstdio>

#include "analysis/audit/decaying_noise_fit.hpp"
#include "analysis/audit/effect_catalog.hpp"

namespace ms::audit {

namespace {

constexpr double kMinGapImprovementDb = 0.5;  // in-sample gap improvement (tuning seeds: noise floors reach 0.42)
// Room tails of 0.1-2.5 s: longer ones are indistinguishable from a noise floor over a strike.
constexpr double kMinRt60S = 0.1, kMaxRt60S = 2.5;
constexpr double kMinLevelDb = -60.0, kMaxLevelDb = 0.0;

void extend(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train) {
  AuditModel without = model;
  without.reverb = {};
  const DecayingNoiseFit f = fit_decaying_noise(data, without, train, kMinRt60S, kMaxRt60S, kMinLevelDb, kMaxLevelDb);
  model.reverb = {.rt60_s = f.t60_s, .level_db = f.level_db, .enabled = true};
}

Detection detect(const AuditData& data, const AuditModel& current) {
  return detect_by_gap_improvement(data, current, extend, kMinGapImprovementDb,
                                   [](const AuditModel& with, double before, double after) {
                                     char buf[300];
                                     std::snprintf(buf, sizeof buf,
                                                   "a tail common to all bands decays independently of the modes "
                                                   "(RT60 %.2f s, %.1f dB re the direct sound); adding it lowers "
                                                   "the gap from %.2f to %.2f dB",
                                                   with.reverb.rt60_s, with.reverb.level_db, before, after);
                                     return std::string(buf);
                                   });
}

Parameters parameters(const AuditData&, const AuditModel& model) {
  return {{"rt60_s", model.reverb.rt60_s}, {"level_db", model.reverb.level_db}};
}

}  // namespace

Effect reverberation_effect() {
  return {.name = "reverberation", .min_strikes = 1, .penalty_db = 0.05,
          .detect = detect, .extend = extend, .parameters = parameters};
}

}  // namespace ms::audit
