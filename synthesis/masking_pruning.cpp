#include "synthesis/masking_pruning.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "synthesis/bark.hpp"
#include "synthesis/threshold_in_quiet.hpp"

namespace ms {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kLowerSlopeDbPerBark = 25.0;
constexpr double kDbToLn = 0.23025850929940457;  // ln(10)/10: 10^(x/10) = exp(kDbToLn x)

double upper_slope_db_per_bark(double level_db) { return std::max(0.0, 22.0 - level_db / 5.0); }

// M(n,m) exactly as the header writes it. The naive sweep and both sides of the fast max report
// values computed here.
double masking_by(double masker_level_db, double masker_bark, double target_bark, double a_v) {
  if (target_bark <= masker_bark)
    return masker_level_db - a_v - kLowerSlopeDbPerBark * (masker_bark - target_bark);
  return masker_level_db - a_v - upper_slope_db_per_bark(masker_level_db) * (target_bark - masker_bark);
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Maximum of lines over a fixed, sorted set of abscissae (Li Chao tree). A line is a masker: its
// value at Bark x is L - a_v - s (x - z_n), masking_by's upper side, linear in x.
class UpperEnvelope {
 public:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

  explicit UpperEnvelope(const std::vector<double>& xs)
      : xs_(xs), node_(4 * std::max<std::size_t>(xs.size(), 1), Line{0, 0, 0, kNone}) {}

  void insert(double level_db, double bark, double a_v, std::size_t masker) {
    Line line{level_db - a_v, upper_slope_db_per_bark(level_db), bark, masker};
    std::size_t node = 1, lo = 0, hi = xs_.size() - 1;
    while (true) {
      Line& cur = node_[node];
      if (cur.masker == kNone) {
        cur = line;
        return;
      }
      const std::size_t mid = (lo + hi) / 2;
      const bool lo_better = line.at(xs_[lo]) > cur.at(xs_[lo]);
      const bool mid_better = line.at(xs_[mid]) > cur.at(xs_[mid]);
      if (mid_better) std::swap(cur, line);
      if (lo == hi) return;
      if (lo_better != mid_better) {
        node = 2 * node;
        hi = mid;
      } else {
        node = 2 * node + 1;
        lo = mid + 1;
      }
    }
  }

  // The masker with the largest value at xs[i], or kNone.
  std::size_t best_at(std::size_t i) const {
    const double x = xs_[i];
    std::size_t node = 1, lo = 0, hi = xs_.size() - 1, best = kNone;
    double best_value = -kInf;
    while (true) {
      const Line& cur = node_[node];
      if (cur.masker == kNone) return best;  // children are only filled below a filled node
      const double v = cur.at(x);
      if (best == kNone || v > best_value) {
        best = cur.masker;
        best_value = v;
      }
      if (lo == hi) return best;
      const std::size_t mid = (lo + hi) / 2;
      if (i <= mid) {
        node = 2 * node;
        hi = mid;
      } else {
        node = 2 * node + 1;
        lo = mid + 1;
      }
    }
  }

 private:
  struct Line {
    double head_db, slope, bark;  // value at x: head_db - slope (x - bark)
    std::size_t masker;
    double at(double x) const { return head_db - slope * (x - bark); }
  };
  const std::vector<double>& xs_;
  std::vector<Line> node_;
};

// The upper-side power sum U(z) = sum_n 10^((L_n - a_v - s_n (z - z_n))/10) over the inserted
// maskers, i.e. sum_n exp(e_n - r_n z) with rate r_n = c s_n and e_n = c (L_n - a_v) + r_n z_n
// (c = ln 10 / 10). Rates differ per masker, so the sum does not factorise; instead maskers are put in
// buckets of rate width kBucketWidth centred on r_b, where exp(-r_n z) = exp(-r_b z) exp(-eps_n z)
// with |eps_n| <= kBucketWidth/2, and exp(-eps_n z) is replaced by its Taylor polynomial of
// kTaylorTerms terms. A bucket is then the moments sum_n exp(e_n - E_b) eps_n^k / k! (E_b: the
// bucket's largest e_n, which keeps every number in range), evaluated at any z by Horner.
// Error: z <= 13 pi/2 + 3.5 pi/2 = 25.92 Bark for every frequency, so |eps_n z| <= rho = 3.24 and each
// term's Taylor remainder is at most rho^27/27! e^rho = 1.4e-13 of it. Rounding: the signed Taylor
// terms sum to no less than e^(-2 rho) = 1/650 of their magnitudes (~1e-13 relative), and the bucket
// factors, carried from one z to the next by multiplication, drift by ~1e-16 per step: U is good to
// ~1e-11 relative (measured against the naive sum: 4e-14 dB on 3000 random modes).
class RateBuckets {
 public:
  static constexpr double kBucketWidth = 0.25;  // nepers per Bark = 1.09 dB/Bark of slope
  static constexpr std::size_t kTaylorTerms = 27;

  RateBuckets(const std::vector<double>& level_db, double a_v) : a_v_(a_v) {
    // One bucket per rate cell holding a masker, known before any insertion. Cells are few: rates
    // are at most c (22 + 3300/5) = 157 nepers/Bark, as no finite level lies below about -3300 dB
    // (P_n / P_max >= 4.9e-324), so there are at most 630 cells.
    for (double level : level_db) {
      if (level == -kInf) continue;
      const std::size_t cell = cell_of(kDbToLn * upper_slope_db_per_bark(level));
      if (cell >= slot_of_cell_.size()) slot_of_cell_.resize(cell + 1, kNoSlot);
      slot_of_cell_[cell] = 0;
    }
    for (std::size_t cell = 0; cell < slot_of_cell_.size(); ++cell)
      if (slot_of_cell_[cell] != kNoSlot) {
        slot_of_cell_[cell] = cells_.size();
        cells_.push_back(cell);
      }
    const std::size_t n = cells_.size();
    rate_.resize(n);
    for (std::size_t b = 0; b < n; ++b) rate_[b] = (double(cells_[b]) + 0.5) * kBucketWidth;
    scale_.assign(n, -kInf);
    moment_.assign(kTaylorTerms * n, 0.0);
    factor_.assign(n, 0.0);
    horner_.resize(n);
  }

  // Maskers are inserted in ascending Bark, each at or after the last sum_at().
  void insert(double level_db, double bark) {
    const double rate = kDbToLn * upper_slope_db_per_bark(level_db);
    const double e = kDbToLn * (level_db - a_v_) + rate * bark;
    const std::size_t n = cells_.size();
    const std::size_t b = slot_of_cell_[cell_of(rate)];
    if (e > scale_[b]) {
      const double rescale = scale_[b] == -kInf ? 0.0 : std::exp(scale_[b] - e);
      for (std::size_t k = 0; k < kTaylorTerms; ++k) moment_[k * n + b] *= rescale;
      scale_[b] = e;
      factor_[b] = std::exp(e - rate_[b] * z_);
    }
    const double eps = rate - rate_[b];
    double term = std::exp(e - scale_[b]);
    for (std::size_t k = 0; k < kTaylorTerms; ++k) {
      moment_[k * n + b] += term;
      term *= eps * kReciprocal[k];
    }
  }

  // U(z) for z at or above every inserted masker's Bark and the previous z.
  double sum_at(double z) {
    const std::size_t n = cells_.size();
    if (n == 0) return 0.0;
    // factor_b = exp(E_b - r_b z), advanced from the previous z by exp(-r_b dz) =
    // exp(-(cell_b + 0.5) w dz), i.e. powers of exp(-w dz): two exp() per call, not one per bucket.
    const double dz = z - z_;
    if (dz != 0) {
      const double step = std::exp(-kBucketWidth * dz);
      double decay = std::exp(-kBucketWidth * dz * (double(cells_[0]) + 0.5));
      for (std::size_t b = 0; b < n; ++b) {
        if (b > 0) {
          const std::size_t gap = cells_[b] - cells_[b - 1];
          decay *= gap == 1 ? step : std::pow(step, double(gap));
        }
        factor_[b] *= decay;
      }
      z_ = z;
    }
    std::fill(horner_.begin(), horner_.end(), 0.0);
    for (std::size_t k = kTaylorTerms; k-- > 0;) {
      const double* m = moment_.data() + k * n;
      for (std::size_t b = 0; b < n; ++b) horner_[b] = horner_[b] * -z + m[b];
    }
    double total = 0.0;
    for (std::size_t b = 0; b < n; ++b) total += factor_[b] * horner_[b];
    return total;
  }

 private:
  static std::size_t cell_of(double rate) { return std::size_t(rate / kBucketWidth); }  // rate >= 0
  static constexpr std::size_t kNoSlot = std::numeric_limits<std::size_t>::max();
  static constexpr auto kReciprocal = [] {  // 1/(k+1)
    std::array<double, kTaylorTerms> r{};
    for (std::size_t k = 0; k < kTaylorTerms; ++k) r[k] = 1.0 / double(k + 1);
    return r;
  }();

  double a_v_;
  std::vector<std::size_t> slot_of_cell_;  // bucket of each rate cell, or kNoSlot
  std::vector<std::size_t> cells_;         // the cell of each bucket, ascending
  std::vector<double> rate_;    // r_b, the centre of each cell
  std::vector<double> scale_;   // E_b (-inf while empty)
  std::vector<double> moment_;  // [k * buckets + b]
  std::vector<double> factor_;  // exp(E_b - r_b z_), 0 while empty
  double z_ = 0.0;              // where factor_ stands
  std::vector<double> horner_;  // scratch
};

}  // namespace

PruneError::PruneError(std::string field, std::size_t mode, std::string problem)
    : std::invalid_argument((mode == kNoMode ? field : "mode " + std::to_string(mode) + ": " + field) +
                            ": " + problem),
      field_(std::move(field)),
      mode_(mode),
      problem_(std::move(problem)) {}

std::optional<PruneMethod> parse_prune_method(std::string_view name) { return find_enum(kPruneMethodNames, name); }
std::optional<ModeOrder> parse_mode_order(std::string_view name) { return find_enum(kModeOrderNames, name); }
std::optional<MaskingCombine> parse_masking_combine(std::string_view name) {
  return find_enum(kMaskingCombineNames, name);
}
std::string_view to_string(PruneMethod method) { return enum_name(kPruneMethodNames, method); }
std::string_view to_string(ModeOrder order) { return enum_name(kModeOrderNames, order); }
std::string_view to_string(MaskingCombine combine) { return enum_name(kMaskingCombineNames, combine); }

ModeOrder effective_order(const PruneOptions& options) {
  switch (options.method) {
    case PruneMethod::masking: return options.order;
    case PruneMethod::naive: return ModeOrder::naive;
    case PruneMethod::energy: return ModeOrder::energy;
    case PruneMethod::loudness: return ModeOrder::loudness;
  }
  return options.order;
}

void validate_prune_options(const PruneOptions& o) {
  auto check = [](const char* field, double v, double lo, double hi, const char* unit) {
    if (!std::isfinite(v) || v < lo || v > hi)
      throw PruneError(field, PruneError::kNoMode,
                       number(v) + " is outside [" + number(lo) + ", " + number(hi) + "] " + unit);
  };
  check("threshold_db", o.threshold_db, kThresholdDbMin, kThresholdDbMax, "dB");
  check("playback_db", o.playback_db, kPlaybackDbMin, kPlaybackDbMax, "dB SPL");
}

std::vector<double> mode_powers(const ModalModel& model) {
  std::vector<double> power;
  power.reserve(model.modes.size());
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    const Mode& m = model.modes[n];
    if (!std::isfinite(m.freq_hz) || m.freq_hz <= 0)
      throw PruneError("freq_hz", n, "must be a finite number greater than 0, got " + number(m.freq_hz));
    if (!std::isfinite(m.amp) || m.amp < 0)
      throw PruneError("amp", n, "must be a finite number >= 0, got " + number(m.amp));
    if (!std::isfinite(m.decay_per_s) || m.decay_per_s < 0)
      throw PruneError("decay_per_s", n, "must be a finite number > 0, got " + number(m.decay_per_s));
    if (m.decay_per_s == 0)
      throw PruneError("decay_per_s", n,
                       "is 0: a mode that never decays has infinite power amp^2/decay, "
                       "so masking cannot rank it");
    const double p = m.amp * m.amp / m.decay_per_s;
    if (!std::isfinite(p))
      throw PruneError("decay_per_s", n, "power amp^2/decay overflows (amp " + number(m.amp) +
                                             ", decay " + number(m.decay_per_s) + ")");
    power.push_back(p);
  }
  return power;
}

std::vector<double> mode_levels_db(const std::vector<double>& power, double playback_db) {
  const double p_max = power.empty() ? 0.0 : *std::max_element(power.begin(), power.end());
  std::vector<double> level(power.size(), -kInf);
  if (!(p_max > 0)) return level;
  double relative_sum = 0;
  for (double p : power) relative_sum += p / p_max;
  const double offset = playback_db - 10.0 * std::log10(relative_sum);
  for (std::size_t n = 0; n < power.size(); ++n)
    if (power[n] > 0) level[n] = offset + 10.0 * std::log10(power[n] / p_max);
  return level;
}

std::vector<double> masking_threshold_db_naive(const std::vector<double>& bark,
                                               const std::vector<double>& level_db, double a_v,
                                               MaskingCombine combine) {
  const std::size_t n_modes = bark.size();
  std::vector<double> threshold(n_modes);
  for (std::size_t m = 0; m < n_modes; ++m) {
    double acc = combine == MaskingCombine::max ? -kInf : 0.0;
    for (std::size_t n = 0; n < n_modes; ++n) {
      if (n == m || level_db[n] == -kInf) continue;
      const double masking = masking_by(level_db[n], bark[n], bark[m], a_v);
      if (combine == MaskingCombine::max)
        acc = std::max(acc, masking);
      else
        acc += std::pow(10.0, masking / 10.0);
    }
    threshold[m] = combine == MaskingCombine::max ? acc : 10.0 * std::log10(acc);
  }
  return threshold;
}

std::vector<double> masking_threshold_db(const std::vector<double>& bark,
                                         const std::vector<double>& level_db, double a_v,
                                         MaskingCombine combine) {
  const std::size_t n_modes = bark.size();
  std::vector<double> threshold(n_modes, -kInf);
  if (n_modes == 0) return threshold;

  // Sweep the modes in ascending Bark (ties by index). For the mode at sorted position p, the
  // maskers after p have z_n >= z_m (lower side) and those before p have z_n <= z_m (upper side).
  // Maskers at the same Bark may fall on either side: at distance 0 both branches of M are L - a_v.
  std::vector<std::pair<double, std::size_t>> sorted(n_modes);
  for (std::size_t n = 0; n < n_modes; ++n) sorted[n] = {bark[n], n};
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> xs(n_modes);  // Bark per sorted position
  for (std::size_t p = 0; p < n_modes; ++p) xs[p] = sorted[p].first;
  auto is_masker = [&](std::size_t n) { return level_db[n] != -kInf; };

  if (combine == MaskingCombine::max) {
    // Lower side: M = (L_n - 25 z_n) + 25 z_m - a_v, so the best masker after p is the suffix
    // maximum of L_n - 25 z_n.
    constexpr std::size_t kNone = UpperEnvelope::kNone;
    std::vector<std::size_t> best_after(n_modes, kNone);
    std::size_t best = kNone;
    double best_key = -kInf;
    for (std::size_t p = n_modes; p-- > 0;) {
      best_after[p] = best;
      const std::size_t n = sorted[p].second;
      const double key = level_db[n] - kLowerSlopeDbPerBark * bark[n];
      if (is_masker(n) && (best == kNone || key > best_key)) {
        best = n;
        best_key = key;
      }
    }
    // Upper side: the envelope of the maskers before p, each inserted once it has been passed.
    UpperEnvelope upper(xs);
    for (std::size_t p = 0; p < n_modes; ++p) {
      const std::size_t m = sorted[p].second;
      double t = -kInf;
      if (const std::size_t n = best_after[p]; n != kNone) t = masking_by(level_db[n], bark[n], bark[m], a_v);
      if (const std::size_t n = upper.best_at(p); n != kNone)
        t = std::max(t, masking_by(level_db[n], bark[n], bark[m], a_v));
      threshold[m] = t;
      if (is_masker(m)) upper.insert(level_db[m], bark[m], a_v, m);
    }
    return threshold;
  }

  // combine == sum.
  // Lower side: R[p] = sum over sorted positions k >= p of 10^((L_k - a_v - 25 (z_k - z_p))/10),
  // by the recurrence R[p] = w_p + R[p+1] 10^(-2.5 (z_{p+1} - z_p)); every factor is <= 1, so
  // nothing overflows and no term is subtracted. The maskers after p contribute
  // R[p+1] 10^(-2.5 (z_{p+1} - z_p)).
  std::vector<double> after(n_modes, 0.0);  // that contribution, per sorted position
  double suffix = 0.0;
  for (std::size_t p = n_modes; p-- > 0;) {
    after[p] = suffix;
    const std::size_t n = sorted[p].second;
    const double own = is_masker(n) ? std::exp(kDbToLn * (level_db[n] - a_v)) : 0.0;
    const double decay = p > 0 ? std::exp(-kDbToLn * kLowerSlopeDbPerBark * (xs[p] - xs[p - 1])) : 0.0;
    suffix = (own + suffix) * decay;
  }
  // Upper side: the maskers before p, inserted once passed.
  RateBuckets upper(level_db, a_v);
  for (std::size_t p = 0; p < n_modes; ++p) {
    const std::size_t m = sorted[p].second;
    threshold[m] = 10.0 * std::log10(upper.sum_at(xs[p]) + after[p]);
    if (is_masker(m)) upper.insert(level_db[m], bark[m]);
  }
  return threshold;
}

std::vector<std::size_t> order_modes(std::vector<std::size_t> indices, ModeOrder order,
                                     const ModalModel& model, const std::vector<double>& power,
                                     const std::vector<double>& loudness_db) {
  auto key = [&](std::size_t n) {
    switch (order) {
      case ModeOrder::naive: return model.modes[n].amp;
      case ModeOrder::energy: return power[n];
      case ModeOrder::loudness: return loudness_db[n];
    }
    return 0.0;
  };
  std::sort(indices.begin(), indices.end(), [&](std::size_t a, std::size_t b) {
    const double ka = key(a), kb = key(b);
    return ka > kb || (ka == kb && a < b);
  });
  return indices;
}

PruneResult prune_modes(const ModalModel& model, const PruneOptions& options) {
  validate_prune_options(options);
  PruneResult r;
  r.power = mode_powers(model);
  r.level_db = mode_levels_db(r.power, options.playback_db);
  const std::size_t n_modes = model.modes.size();
  r.bark.resize(n_modes);
  r.quiet_db.resize(n_modes);
  for (std::size_t n = 0; n < n_modes; ++n) {
    r.bark[n] = bark_zwicker_terhardt(model.modes[n].freq_hz);
    r.quiet_db[n] = threshold_in_quiet_db_spl(model.modes[n].freq_hz);
  }
  r.masking_db = masking_threshold_db(r.bark, r.level_db, options.threshold_db, options.combine);
  r.loudness_db.resize(n_modes);
  r.audible.resize(n_modes);
  std::vector<std::size_t> candidates;
  for (std::size_t n = 0; n < n_modes; ++n) {
    const double threshold = std::max(r.masking_db[n], r.quiet_db[n]);
    r.loudness_db[n] = r.level_db[n] - threshold;
    r.audible[n] = r.power[n] > 0 && r.level_db[n] >= threshold;
    if (options.method != PruneMethod::masking || r.audible[n])
      candidates.push_back(n);
    else
      r.dropped.push_back(n);
  }
  r.kept = order_modes(std::move(candidates), effective_order(options), model, r.power, r.loudness_db);
  return r;
}

ModalModel progressive_model(const ModalModel& model, const PruneResult& result, std::size_t k) {
  ModalModel out;
  out.hit_point_names = model.hit_point_names;
  out.hit_gains.resize(model.hit_gains.size());
  const std::size_t count = std::min(k, result.kept.size());
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t n = result.kept[i];
    out.modes.push_back(model.modes[n]);
    for (std::size_t h = 0; h < model.hit_gains.size(); ++h)
      out.hit_gains[h].push_back(model.hit_gains[h][n]);
  }
  return out;
}

}  // namespace ms
