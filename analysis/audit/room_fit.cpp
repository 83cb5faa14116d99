#include "analysis/audit/room_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "analysis/audit/gap_target.hpp"
#include "analysis/audit/grid_cross_validation.hpp"
#include "analysis/audit/room_power.hpp"
#include "analysis/estimation/local_search.hpp"
#include "synthesis/resonator_bank.hpp"

namespace ms::audit {

namespace {

using Rates = std::array<double, kRoomBands>;

constexpr double kMinRead = 0.1, kMaxRead = 3.0;  // a mode's amplitude read again: within these factors

// Minimum of f over [lo, hi] by golden-section search (`steps` evaluations after two).
template <class F>
double golden_minimum(F f, double lo, double hi, int steps, double& value) {
  constexpr double kPhi = 0.6180339887498949;
  double c = hi - kPhi * (hi - lo), d = lo + kPhi * (hi - lo), fc = f(c), fd = f(d);
  for (int i = 0; i < steps; ++i) {
    if (fc < fd) {
      hi = d;
      d = c;
      fd = fc;
      c = hi - kPhi * (hi - lo);
      fc = f(c);
    } else {
      lo = c;
      c = d;
      fc = fd;
      d = lo + kPhi * (hi - lo);
      fd = f(d);
    }
  }
  value = std::min(fc, fd);
  return fc < fd ? c : d;
}

// Everything a candidate room is scored with: the strikes' renderings and footprints, and the target.
class RoomObjective {
 public:
  // The strikes rendered with the dry amplitudes of `room` (none: the measured ones).
  RoomObjective(const AuditData& data, const AuditModel& without, const std::vector<std::size_t>& strikes,
                const Room* room = nullptr)
      : data_(data), model_(without), target_(data, strikes), fs_(data.measured.sample_rate_hz) {
    for (std::size_t r = 0; r < kResolutions; ++r) room_grids_[r] = room_grid(data.measured.grids[r]);
    rebase(room);
  }

  // Renders the strikes with the dry amplitudes of `room` (none: the measured amplitudes, each mode's
  // room_gain then applied in closed form): candidates near it are scored with small corrections.
  void rebase(const Room* room) {
    model_.room = room ? *room : Room{};
    const RoomRates rates = room ? room_rates(*room, fs_) : RoomRates{};
    base_.clear();
    footprints_.clear();
    owners_.clear();
    heard_.fill(false);
    for (std::size_t s : target_.strikes()) {
      base_.push_back(predict_spectra(model_, data_, s, nullptr, false));
      std::vector<std::size_t> owner;
      const ModalModel modal = dry_strike_model(model_, s, fs_, &owner);
      std::array<RoomFootprint, kResolutions> fp;
      for (std::size_t r = 0; r < kResolutions; ++r) {
        fp[r] = room_footprint(data_.measured.grids[r], room_grids_[r], modal, room ? &rates : nullptr);
        for (RoomFootprint::ModeTerms& m : fp[r].modes) {
          if (!room) m.extra_power = std::pow(model_.modes[owner[m.owner]].room_gain, 2);
          m.answer = model_.modes[owner[m.owner]].room_answer;
        }
      }
      for (const RoomFootprint::ModeTerms& m : fp[kDecay].modes) heard_[m.octave] = true;
      footprints_.push_back(std::move(fp));
      owners_.push_back(std::move(owner));
    }
  }

  // Each model mode's amplitude (and with `answers` the room's answer to it) read again from the
  // spectrograms with the room (k, sigma2) in the model, one mode after another: the factor on its dry
  // amplitude in [kMinRead, kMaxRead] and the answer within what the room's noise allows
  // (mode_answer_range) that minimise the mean gap, or factor 0 where leaving the mode out does better
  // and `may_drop` allows it.
  ModeReading read_amplitudes(const Rates& k, double sigma2, const std::vector<bool>& may_drop, bool answers) {
    const RoomRates rates{k, sigma2};
    const std::size_t modes = model_.modes.size(), strikes = base_.size();
    // A mode's power in one cell: its direct part and its reverberant part at answer 1.
    struct Cell {
      std::size_t cell;
      double direct, reverberant;
    };
    // Per strike and resolution: the prediction; per model mode its power per cell.
    std::vector<Spectra> predicted(strikes);
    std::vector<std::vector<std::vector<Cell>>> power(modes, std::vector<std::vector<Cell>>(strikes * kResolutions));
    std::vector<double> sum(strikes, 0.0), cells(strikes, 0.0);
    ModeReading out{std::vector<double>(modes, 1.0), {}};
    for (const AuditMode& m : model_.modes) out.answer.push_back(m.room_answer);
    std::vector<std::pair<double, double>> range(modes, {1.0, 1.0});  // of the answer (read only with `answers`)
    std::vector<bool> ranged(modes, false);
    for (std::size_t i = 0; i < strikes; ++i) {
      predicted[i] = base_[i];
      for (std::size_t r = 0; r < kResolutions; ++r) {
        const SpectrogramGrid& g = data_.measured.grids[r];
        add_room_power(predicted[i][r], g, room_grids_[r], footprints_[i][r], rates);
        const RoomFrameSums sums = room_frame_sums(g, rates);
        const std::size_t frames = predicted[i][r].frames, bands = predicted[i][r].bands;
        std::vector<double> rendered(frames), added(frames), reverberant(frames);
        std::vector<std::vector<double>> direct(modes), reverb(modes);
        for (const RoomFootprint::ModeTerms& m : footprints_[i][r].modes) {
          const std::size_t n = owners_[i][m.owner];
          if (answers && !ranged[n]) {  // from the first strike's rendering (a doublet's pair share a band)
            range[n] = mode_answer_range(m, rates);
            ranged[n] = true;
          }
          if (direct[n].empty()) {
            direct[n].assign(frames * bands, 0.0);
            reverb[n].assign(frames * bands, 0.0);
          }
          mode_frame_powers(m, g, rates, sums, frames, rendered.data(), added.data(), reverberant.data());
          const double dry = mode_dry_factor(m, rates);
          for (std::size_t fr = 0; fr < frames; ++fr)
            for (const auto& [b, l] : m.leakage) {
              direct[n][fr * bands + b] += l * dry * rendered[fr];
              reverb[n][fr * bands + b] += l * reverberant[fr];
            }
        }
        // A cell where the mode at its largest (kMaxRead, the highest answer) stays below a millionth of
        // the floor's power moves no level by more than 5e-6 dB: it is not visited.
        const double negligible = 1e-6 * target_.floor_power(i, r) / (kMaxRead * kMaxRead);
        for (std::size_t n = 0; n < modes; ++n) {
          const double a_max = std::max({1.0, out.answer[n], answers ? range[n].second : 0.0});
          for (std::size_t c = 0; c < direct[n].size(); ++c)
            if (direct[n][c] + a_max * reverb[n][c] > negligible)
              power[n][i * kResolutions + r].push_back({c, direct[n][c], reverb[n][c]});
        }
        const std::vector<double>& measured = target_.measured_db(i, r);
        const double floor = target_.floor_db(i, r);
        for (std::size_t c = 0; c < measured.size(); ++c) {
          const double b = std::max(quick_level_db(predicted[i][r].power[c]), floor);
          if (measured[c] <= floor && b <= floor) continue;
          sum[i] += std::abs(b - measured[c]);
          cells[i] += 1.0;
        }
      }
    }
    // A mode's power in a cell at answer a (as mode_frame_powers: never below kMinAnsweredShare of the
    // direct part).
    const auto own_power = [](const Cell& c, double a) {
      return std::max(c.direct + a * c.reverberant, kMinAnsweredShare * c.direct);
    };
    // The level now of each of mode n's cells, in the order gap_with visits them: the same for every
    // factor tried on the mode, so its logarithm is taken once.
    std::vector<double> now_db;
    const auto level_now = [&](std::size_t n) {
      now_db.clear();
      for (std::size_t i = 0; i < strikes; ++i)
        for (std::size_t r = 0; r < kResolutions; ++r) {
          const double floor = target_.floor_db(i, r);
          const std::vector<double>& p = predicted[i][r].power;
          for (const Cell& c : power[n][i * kResolutions + r]) now_db.push_back(std::max(quick_level_db(p[c.cell]), floor));
        }
    };
    // Mean gap with mode n's amplitude scaled by x and its answer a (all else as predicted now;
    // level_now(n) called since the last change).
    const auto gap_with = [&](std::size_t n, double x, double a, bool apply) {
      const double a_now = out.answer[n];
      double total = 0.0;
      std::size_t visited = 0;
      for (std::size_t i = 0; i < strikes; ++i) {
        double s = sum[i], c = cells[i];
        for (std::size_t r = 0; r < kResolutions; ++r) {
          const std::vector<double>& measured = target_.measured_db(i, r);
          const double floor = target_.floor_db(i, r);
          std::vector<double>& p = predicted[i][r].power;
          for (Cell& own : power[n][i * kResolutions + r]) {
            const std::size_t cell = own.cell;
            const double now = now_db[visited++];
            const double next_power = std::max(p[cell] + x * x * own_power(own, a) - own_power(own, a_now), 1e-300);
            const double next = std::max(quick_level_db(next_power), floor);
            const bool was = !(measured[cell] <= floor && now <= floor), is = !(measured[cell] <= floor && next <= floor);
            s += (is ? std::abs(next - measured[cell]) : 0.0) - (was ? std::abs(now - measured[cell]) : 0.0);
            c += double(is) - double(was);
            if (apply) {
              p[cell] = next_power;
              own.direct *= x * x;
              own.reverberant *= x * x;
            }
          }
        }
        if (apply) {
          sum[i] = s;
          cells[i] = c;
        }
        total += c > 0.0 ? s / c : 0.0;
      }
      if (apply) out.answer[n] = a;
      return total / double(std::max<std::size_t>(strikes, 1));
    };
    for (std::size_t n = 0; n < modes; ++n) {
      level_now(n);
      double best_a = out.answer[n], best_value = gap_with(n, 1.0, best_a, false), best_x = 1.0, value = 0.0;
      const auto read_x = [&] {
        const double lx = golden_minimum([&](double v) { return gap_with(n, std::exp(v), best_a, false); },
                                         std::log(kMinRead), std::log(kMaxRead), 10, value);
        if (value < best_value) { best_value = value; best_x = std::exp(lx); }
      };
      read_x();
      // The answer, then the amplitude again (a lower answer lowers the level the mode settles at).
      if (answers && range[n].second > range[n].first) {
        const double a = golden_minimum([&](double v) { return gap_with(n, best_x, v, false); }, range[n].first,
                                        range[n].second, 10, value);
        if (value < best_value) {
          best_value = value;
          best_a = a;
          read_x();
        }
      }
      if (may_drop[n] && gap_with(n, 0.0, best_a, false) < best_value) best_x = 0.0;
      out.factor[n] = best_x;
      gap_with(n, best_x, best_a, true);
    }
    return out;
  }

  // Gap of each strike with the room (k, sigma2).
  const std::vector<double>& strike_gaps(const Rates& k, double sigma2) {
    const RoomRates rates{k, sigma2};
    gaps_.assign(base_.size(), 0.0);
    for (std::size_t i = 0; i < base_.size(); ++i) {
      scratch_ = base_[i];
      for (std::size_t r = 0; r < kResolutions; ++r)
        add_room_power(scratch_[r], data_.measured.grids[r], room_grids_[r], footprints_[i][r], rates);
      gaps_[i] = target_.strike_gap(i, scratch_);
    }
    return gaps_;
  }

  double gap(const Rates& k, double sigma2) {
    const std::vector<double>& g = strike_gaps(k, sigma2);
    double sum = 0.0;
    for (double v : g) sum += v;
    return g.empty() ? 0.0 : sum / double(g.size());
  }

  double sample_rate() const { return fs_; }
  // Octave bands holding a mode (others can only matter through the onset's spectrum).
  bool heard(std::size_t band) const { return heard_[band]; }

 private:
  const AuditData& data_;
  AuditModel model_;
  GapTarget target_;
  double fs_;
  std::array<RoomGrid, kResolutions> room_grids_;
  std::vector<Spectra> base_;
  std::vector<std::array<RoomFootprint, kResolutions>> footprints_;
  std::vector<std::vector<std::size_t>> owners_;  // per strike: the model mode of each rendered mode
  std::array<bool, kRoomBands> heard_{};
  Spectra scratch_;
  std::vector<double> gaps_;
};

double k_of(double rt60_s, double fs) { return std::log(1000.0) / (rt60_s * fs); }

// RT60 over the octave bands: log RT60 = a + b u + c (u^2 - 1/2) with u from -1 (125 Hz) to 1 (8 kHz),
// a smooth curve as rooms have (absorption changes slowly with frequency); bands without a mode are not
// seen by the gap, and a free value per band would follow its noise.
std::array<double, kRoomBands> log_rt60_curve(double a, double b, double c) {
  std::array<double, kRoomBands> lt{};
  for (std::size_t i = 0; i < kRoomBands; ++i) {
    const double u = (double(i) - 3.0) / 3.0;
    lt[i] = std::clamp(a + b * u + c * (u * u - 0.5), std::log(kMinRoomRt60S), std::log(kMaxRoomRt60S));
  }
  return lt;
}

// The curve's coefficients (a, b, c) nearest a room's log RT60s, by least squares: u is orthogonal to
// 1 and to u^2 - 1/2 over the seven bands, so b is a projection; a and c solve a 2 x 2 system.
std::array<double, 3> curve_of(const Room& room) {
  double n = 0.0, s = 0.0, q = 0.0, uu = 0.0, y1 = 0.0, yu = 0.0, yv = 0.0;
  for (std::size_t i = 0; i < kRoomBands; ++i) {
    const double u = (double(i) - 3.0) / 3.0, v = u * u - 0.5, lt = std::log(room.rt60_s[i]);
    n += 1.0;
    s += v;
    q += v * v;
    uu += u * u;
    y1 += lt;
    yu += lt * u;
    yv += lt * v;
  }
  const double det = n * q - s * s;
  return {(q * y1 - s * yv) / det, yu / uu, (n * yv - s * y1) / det};
}

}  // namespace

RoomFit fit_room(const AuditData& data, const AuditModel& without, const std::vector<std::size_t>& strikes,
                 bool coarse_only, const Room* start) {
  RoomObjective objective(data, without, strikes);
  const double fs = objective.sample_rate();
  const auto rates_of = [&](const std::array<double, kRoomBands>& log_rt60) {
    Rates k{};
    for (std::size_t b = 0; b < kRoomBands; ++b) k[b] = k_of(std::exp(log_rt60[b]), fs);
    return k;
  };
  // 1. One RT60 for every band and the DRR, on a grid, against the measured amplitudes.
  double best = 1e300, lt_best = 0.0, drr_best = 0.0;
  std::vector<std::vector<double>> table;  // [candidate][strike] gaps, for the cross-validated score
  // (coarse_only: a coarser grid, 4 x 6.)
  const std::vector<double> log_rt60s = coarse_only ? std::vector<double>{-1.7, -0.9, -0.1, 0.7}
                                                    : std::vector<double>{-1.9, -1.2, -0.6, -0.1, 0.4, 1.0};
  const double drr_step = (kMaxRoomDrrDb - kMinRoomDrrDb) / (coarse_only ? 5.0 : 7.0);
  for (double lt : log_rt60s)
    for (double drr = kMinRoomDrrDb; drr <= kMaxRoomDrrDb + 1e-9; drr += drr_step) {
      const Rates k = rates_of(log_rt60_curve(lt, 0.0, 0.0));
      table.push_back(objective.strike_gaps(k, room_sigma2(k, drr, fs)));
      double gap = 0.0;
      for (double v : table.back()) gap += v;
      gap /= double(std::max<std::size_t>(table.back().size(), 1));
      if (gap < best) { best = gap; lt_best = lt; drr_best = drr; }
    }
  // 2. The curve's three coefficients and the level, twice: each time from renderings with the dry
  // amplitudes of the room found so far (the closed-form corrections stay small).
  std::array<double, 4> p{lt_best, 0.0, 0.0, std::log(room_sigma2(rates_of(log_rt60_curve(lt_best, 0.0, 0.0)), drr_best, fs))};
  const auto room_of = [&](const std::array<double, 4>& q) {
    Room room;
    room.enabled = true;
    const auto lt = log_rt60_curve(q[0], q[1], q[2]);
    for (std::size_t b = 0; b < kRoomBands; ++b) room.rt60_s.push_back(std::exp(lt[b]));
    room.drr_db = room_drr_db({rates_of(lt), std::exp(q[3])}, fs);
    return room;
  };
  const auto gap_of = [&](const std::vector<double>& q) {
    return objective.gap(rates_of(log_rt60_curve(q[0], q[1], q[2])), std::exp(q[3]));
  };
  RoomFit fit;
  fit.grid_cv_gap_db = leave_one_out_gap(table);
  for (std::size_t b = 0; b < kRoomBands; ++b) fit.band_measured.push_back(objective.heard(b));
  if (coarse_only) {
    fit.room = room_of(p);
    fit.gap_db = best;
    return fit;
  }
  // The start and the grid's best compared each from its own rendering (far from the measured
  // amplitudes the closed-form corrections are not small).
  bool based = false;
  if (start && start->rt60_s.size() == kRoomBands) {
    const std::array<double, 3> c = curve_of(*start);
    const std::array<double, 4> q{c[0], c[1], c[2], std::log(room_sigma2(rates_of(log_rt60_curve(c[0], c[1], c[2])), start->drr_db, fs))};
    const Room grid = room_of(p), begun = room_of(q);
    objective.rebase(&grid);
    const double grid_gap = gap_of({p.begin(), p.end()});
    objective.rebase(&begun);
    if (gap_of({q.begin(), q.end()}) < grid_gap) {
      p = q;
      based = true;
    }
  }
  BoxedSearchOptions search;
  search.lower = {std::log(kMinRoomRt60S), -3.0, -3.0, p[3] - 12.0};
  search.upper = {std::log(kMaxRoomRt60S), 3.0, 3.0, p[3] + 12.0};
  search.step = {0.3, 0.3, 0.3, 0.7};
  for (std::size_t evaluations : {70, 25}) {
    const Room current = room_of(p);
    if (!based) objective.rebase(&current);
    based = false;
    search.max_evaluations = evaluations;
    const BoxedSearchResult found = nelder_mead_boxed(gap_of, {p.begin(), p.end()}, search);
    std::copy(found.x.begin(), found.x.end(), p.begin());
    best = found.value;
  }
  fit.room = room_of(p);
  fit.gap_db = best;
  // The coarse grid's rooms (one RT60 for every band) can all lie far from the fitted one; held-out
  // strikes also score a small grid around it (its RT60s scaled by 0.7-1.4, its level -6 to +6 dB).
  std::vector<std::vector<double>> local;
  for (double lt : {-0.35, 0.0, 0.35})
    for (double level : {-1.4, -0.7, 0.0, 0.7, 1.4})
      local.push_back(objective.strike_gaps(rates_of(log_rt60_curve(p[0] + lt, p[1], p[2])), std::exp(p[3] + level)));
  fit.grid_cv_gap_db = std::min(fit.grid_cv_gap_db, leave_one_out_gap(local));
  return fit;
}

void ModeReading::apply(AuditModel& model) const {
  for (std::size_t n = 0; n < factor.size(); ++n) {
    model.modes[n].room_gain *= factor[n];
    model.modes[n].room_answer = answer[n];
  }
}

ModeReading read_mode_amplitudes(const AuditData& data, const AuditModel& without, const Room& room,
                                 const std::vector<std::size_t>& strikes, const std::vector<bool>& may_drop) {
  RoomObjective objective(data, without, strikes, &room);
  const RoomRates rates = room_rates(room, objective.sample_rate());
  return objective.read_amplitudes(rates.k_per_sample, rates.sigma2, may_drop, false);
}

std::optional<double> read_amplitudes_in_room(const AuditData& data, AuditModel& model,
                                              const std::vector<std::size_t>& strikes) {
  if (!model.room.enabled) return std::nullopt;
  // Tuning rooms 42100-42139: the first pass lowers the gap by about 0.3 dB, the second by 0.05-0.1,
  // later ones by less. Each pass renders the strikes once: the rendering that scores a pass reads the next.
  constexpr int kMaxPasses = 2;
  constexpr double kMinGainDb = 0.005;
  const RoomRates rates = room_rates(model.room, data.measured.sample_rate_hz);
  const std::vector<bool> drop_none(model.modes.size(), false);
  std::optional<RoomObjective> objective;
  objective.emplace(data, model, strikes, &model.room);
  double gap = objective->gap(rates.k_per_sample, rates.sigma2);
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    AuditModel next = model;
    const ModeReading read = objective->read_amplitudes(rates.k_per_sample, rates.sigma2, drop_none, true);
    read.apply(next);
    objective.emplace(data, next, strikes, &next.room);
    const double next_gap = objective->gap(rates.k_per_sample, rates.sigma2);
    if (next_gap > gap - kMinGainDb) return gap;
    model = std::move(next);
    gap = next_gap;
  }
  return gap;
}

}  // namespace ms::audit
