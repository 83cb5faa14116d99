#include "analysis/audit/audit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "analysis/audit/baseline_fit.hpp"
#include "analysis/audit/parallel_indices.hpp"
#include "analysis/audit/repeatability_floor.hpp"

namespace ms::audit {

AuditData make_audit_data(const std::vector<Recording>& recordings, const AuditOptions& options) {
  AuditData data;
  data.measured = prepare_strikes(recordings, options.strikes);
  std::vector<std::vector<Mode>> modes;
  for (const Strike& s : data.measured.strikes) modes.push_back(s.features.modes);
  data.tracks = match_modes(modes, options.matching);
  data.strike_variation_db = strike_variation(data.measured);
  return data;
}

std::vector<ModeResidual> mode_residuals(const AuditData& data, const AuditModel& model) {
  std::vector<ModeResidual> out;
  for (std::size_t s = 0; s < data.strike_count(); ++s)
    for (std::size_t n = 0; n < model.modes.size(); ++n) {
      const AuditMode& m = model.modes[n];
      if (m.track < 0) continue;
      const TrackObservation& o = data.tracks[std::size_t(m.track)].strikes[s];
      if (!o.present) continue;
      const double d = strike_decay(model, s, n);
      const double a = strike_amp(model, s, n);
      out.push_back({s, m.freq_hz, (o.freq_hz - m.freq_hz) / m.freq_hz, (o.decay_per_s - d) / d,
                     20.0 * std::log10(o.amp / a)});
    }
  return out;
}

namespace {

GapLocation locate(const AuditData& data, const AuditModel& model, const std::vector<GapMap>& maps) {
  GapLocation loc;
  const SpectrogramGrid& g = data.measured.grids[kDecay];
  std::vector<double> band_sum(g.bands, 0.0), band_n(g.bands, 0.0), time_sum(g.frames, 0.0), time_n(g.frames, 0.0);
  for (const GapMap& m : maps) {
    loc.strike_gap_db.push_back(m.gap_db);
    for (std::size_t f = 0; f < m.frames; ++f)
      for (std::size_t b = 0; b < m.bands; ++b) {
        const double v = m.diff_db[f * m.bands + b];
        if (std::isnan(v)) continue;
        band_sum[b] += std::abs(v);
        band_n[b] += 1;
        time_sum[f] += std::abs(v);
        time_n[f] += 1;
      }
  }
  for (std::size_t b = 0; b < g.bands; ++b) loc.band_gap_db.push_back(band_n[b] > 0 ? band_sum[b] / band_n[b] : 0.0);
  for (std::size_t f = 0; f < g.frames; ++f) loc.time_gap_db.push_back(time_n[f] > 0 ? time_sum[f] / time_n[f] : 0.0);
  // Modes ranked by their mean |amplitude residual| + |decay residual| (in dB over the first second).
  std::vector<std::pair<double, std::size_t>> score(model.modes.size(), {0.0, 0});
  for (std::size_t n = 0; n < score.size(); ++n) score[n].second = n;
  for (const ModeResidual& r : mode_residuals(data, model)) {
    for (std::size_t n = 0; n < model.modes.size(); ++n)
      if (model.modes[n].freq_hz == r.freq_hz)
        score[n].first += std::abs(r.amp_db) + 8.686 * std::abs(r.decay_rel) * model.modes[n].decay_per_s;
  }
  std::sort(score.begin(), score.end(), [](auto& a, auto& b) { return a.first > b.first; });
  for (std::size_t i = 0; i < score.size() && i < 5; ++i) loc.worst_modes.push_back(score[i].second);
  return loc;
}

// The object's shapes per given mode onto the baseline's modes (a merged pair: its members' energy).
void place_shapes(const ObjectShapes& shapes, const ModalModel& given, const std::vector<std::size_t>& audit_mode_of_given,
                  AuditModel& model) {
  if (shapes.positions.empty()) return;
  HitPattern& hit = model.hit;
  hit.positions = shapes.positions;
  hit.home_position = shapes.home_position;
  hit.shape_ln.assign(shapes.positions.size(), std::vector<double>(model.modes.size(), 0.0));
  for (std::size_t p = 0; p < shapes.positions.size(); ++p) {
    std::vector<double> there(model.modes.size(), 0.0), home(model.modes.size(), 0.0);
    for (std::size_t i = 0; i < given.modes.size(); ++i) {
      const double a2 = given.modes[i].amp * given.modes[i].amp;
      there[audit_mode_of_given[i]] += a2 * std::exp(2.0 * shapes.shape_ln[p][i]);
      home[audit_mode_of_given[i]] += a2;
    }
    for (std::size_t j = 0; j < model.modes.size(); ++j)
      if (home[j] > 0.0) hit.shape_ln[p][j] = 0.5 * std::log(there[j] / home[j]);
  }
}

// What the training strikes share is read from three of them at least (four strikes, one held out): from
// one or two it is their own values (two strikes of a bell, one free and one muted, would name nothing).
constexpr std::size_t kMinStrikesForRival = 4;

// Whether a candidate's held-out gap is not above its strike-free rival's (the same extension, every
// strike given what the training strikes share) by more than the candidate's penalty; its note says
// which, with both gaps.
bool beats_strike_free_rival(const AuditData& data, const Recipe& recipe, const TrainedFolds& trained, const Effect& e,
                             Candidate& c) {
  Effect rival = e;
  rival.extend = e.strike_free_rival;
  rival.adapt = nullptr;
  Recipe with_rival = recipe;
  with_rival.effects.push_back(&rival);
  const double rival_db = cross_validated_gap(data, with_rival, nullptr, nullptr, &trained);
  const bool beats = c.cv_gap_db < rival_db + e.penalty_db;
  char buf[240];
  std::snprintf(buf, sizeof buf, "; held out it leaves %.2f dB, and %.2f dB with what the strikes share alone: what it "
                "gains is %s", c.cv_gap_db, rival_db, beats ? "the strikes' own" : "not the strikes' own, so it is not named");
  c.note += buf;
  return beats;
}

std::vector<GapMap> maps_of(const AuditData& data, const AuditModel& model) {
  std::vector<GapMap> maps;
  for (std::size_t s = 0; s < data.strike_count(); ++s) maps.push_back(strike_gap(model, data, s));
  return maps;
}

}  // namespace

AuditResult run_audit(const AuditData& data, const std::optional<ModalModel>& given, const AuditOptions& options) {
  if (data.strike_count() < 2)
    throw AuditError("an audit needs at least 2 strikes of the object (support_damping and contact_duration "
                     "compare strikes, and the gap is checked on held-out strikes); got " +
                     std::to_string(data.strike_count()));
  if (data.tracks.empty()) throw AuditError("no mode recurs in at least half of the strikes: are they the same object?");
  AuditResult result;
  result.metric = kGapMetric;
  result.strikes = data.strike_count();
  Recipe recipe;
  if (given) {
    std::vector<std::size_t> audit_mode_of_given;
    recipe.given = baseline_from_model(*given, data, &audit_mode_of_given);
    place_shapes(options.object_shapes, *given, audit_mode_of_given, *recipe.given);
  }
  const std::vector<Effect> catalog = effect_catalog();
  AuditModel current;
  double gap = in_sample_gap(data, recipe, &current);
  std::vector<AuditModel> folds;  // the current recipe's fold models (for the repeatability floor)
  TrainedFolds trained;           // ... and before each held-out strike's latent values (candidates start there)
  double cv = cross_validated_gap(data, recipe, &folds, &result.strike_cv_gap_before_db, nullptr, &trained);
  result.baseline = current;
  result.modes = current.modes.size();
  result.gap_before_db = gap;
  result.cv_gap_before_db = cv;
  for (const Effect& e : catalog)
    if (data.strike_count() < e.min_strikes)
      result.untested.push_back(e.name + " needs at least " + std::to_string(e.min_strikes) + " strikes");
  while (result.named.size() < options.max_effects) {
    std::vector<Candidate> round;
    // Per tried candidate that passed: its effect, detection and held-out fold models.
    struct Passed {
      const Effect* effect;
      Detection detection;
      std::vector<AuditModel> folds;
      TrainedFolds trained;
      double cv_gap_db, improvement_db;
    };
    std::vector<Passed> passed;
    const auto most_improved = [&passed]() {
      Passed* top = nullptr;
      for (Passed& p : passed)
        if (!top || p.improvement_db > top->improvement_db) top = &p;
      return top;
    };
    // Why an effect is not tried this round, if it is not: already in the recipe or named (nothing to
    // say), too few strikes, or (a generic effect) something more specific passed before it.
    const auto not_tried = [&](const Effect& e) -> std::optional<std::string> {
      if (std::find(recipe.effects.begin(), recipe.effects.end(), &e) != recipe.effects.end()) return "";
      for (const NamedEffect& n : result.named)
        if (n.effect == e.name) return "";
      if (data.strike_count() < e.min_strikes) return "needs at least " + std::to_string(e.min_strikes) + " strikes";
      if (const Passed* specific = e.generic ? most_improved() : nullptr)
        return "not tried this round: " + specific->effect->name + " explains the strikes more specifically";
      return std::nullopt;
    };
    // The specific effects' detectors read only the data and the current model, so they run side by
    // side (the room's alone takes seconds); a generic effect is tried only when nothing passed before
    // it, one after another.
    std::vector<const Effect*> specific;
    for (const Effect& e : catalog)
      if (!e.generic && !not_tried(e)) specific.push_back(&e);
    std::vector<Detection> specific_detection(specific.size());
    parallel_indices(specific.size(), [&](std::size_t i) { specific_detection[i] = specific[i]->detect(data, current); });
    for (const bool generic : {false, true})
    for (const Effect& e : catalog) {
      if (e.generic != generic) continue;
      const std::optional<std::string> skip = not_tried(e);
      if (skip && skip->empty()) continue;
      Candidate c;
      c.effect = e.name;
      if (skip) {
        c.note = *skip;
        round.push_back(c);
        continue;
      }
      c.tested = true;
      const Detection det = generic ? e.detect(data, current)
                                    : specific_detection[std::size_t(std::ranges::find(specific, &e) - specific.begin())];
      c.statistic = det.statistic;
      c.detector_passes = det.passes;
      c.note = det.evidence;
      if (det.passes) {
        Recipe with = recipe;
        with.effects.push_back(&e);
        std::vector<AuditModel> with_folds;
        TrainedFolds with_trained;
        c.cv_gap_db = cross_validated_gap(data, with, &with_folds, nullptr, &trained, &with_trained);
        c.improvement_db = cv - c.cv_gap_db - e.penalty_db;
        const bool strikes_own = c.improvement_db <= 0.0 || !e.strike_free_rival ||
                                 data.strike_count() < kMinStrikesForRival ||
                                 beats_strike_free_rival(data, recipe, trained, e, c);
        if (strikes_own && (c.improvement_db > 0.0 || (det.held_out_blind && cv - c.cv_gap_db >= -e.penalty_db)))
          passed.push_back({&e, det, std::move(with_folds), std::move(with_trained), c.cv_gap_db, c.improvement_db});
      }
      round.push_back(c);
    }
    // The largest held-out improvement, unless another passing effect explains its evidence too.
    Passed* chosen = most_improved();
    for (Passed& p : passed)
      if (chosen && std::ranges::count(p.detection.precedes, chosen->effect->name) > 0) {
        chosen = &p;
        break;
      }
    const Effect* best = chosen ? chosen->effect : nullptr;
    result.rounds.push_back(round);
    if (!best) break;
    recipe.effects.push_back(best);
    AuditModel next = fit_last_effect(data, recipe, current, chosen->detection.extended);
    const double next_gap = mean_gap(next, data);
    result.named.push_back({best->name, gap, next_gap, cv - chosen->cv_gap_db, best->parameters(data, next),
                            chosen->detection.evidence, 0.0, chosen->improvement_db <= 0.0});
    gap = next_gap;
    cv = chosen->cv_gap_db;
    folds = std::move(chosen->folds);
    trained = std::move(chosen->trained);
    current = std::move(next);
  }
  result.final_model = current;
  result.gap_after_db = gap;
  result.cv_gap_after_db = cv;
  const RepeatabilityFloor repeatability = repeatability_floor(data, folds);
  result.floor_db = repeatability.floor_db;
  result.strike_floor_db = repeatability.strike_floor_db;
  result.strike_cv_gap_after_db = repeatability.strike_gap_db;
  result.share_above_floor = share_above_floor(result.cv_gap_before_db - cv, result.cv_gap_before_db, repeatability.floor_db);
  result.left_shared = shared_residual(repeatability);
  for (NamedEffect& n : result.named)
    n.share_above_floor = share_above_floor(n.cv_improvement_db, result.cv_gap_before_db, repeatability.floor_db);
  result.before = maps_of(data, result.baseline);
  result.after = maps_of(data, result.final_model);
  result.residuals_before = mode_residuals(data, result.baseline);
  result.residuals_after = mode_residuals(data, result.final_model);
  result.location = locate(data, result.baseline, result.before);
  for (double g : result.baseline.gain) result.strike_gain_db.push_back(20.0 * std::log10(std::max(g, 1e-12)));
  std::vector<double> spreads;
  for (const ModeTrack& t : data.tracks) {
    double lo = 1e300, hi = 0.0;
    for (const TrackObservation& o : t.strikes)
      if (o.present) { lo = std::min(lo, o.decay_per_s); hi = std::max(hi, o.decay_per_s); }
    if (hi > 0 && t.presence() >= 2) spreads.push_back((hi - lo) / lo);
  }
  result.decay_spread = median(spreads);
  return result;
}

}  // namespace ms::audit
