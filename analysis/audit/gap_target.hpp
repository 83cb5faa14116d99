// The gap of many candidate predictions against the same measured strikes (a fit evaluates hundreds):
// the measured levels are clamped to their floors once; the arithmetic is gap_map's, with the model's
// levels taken to within 1e-6 dB by a polynomial.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "analysis/audit/audit_model.hpp"

namespace ms::audit {

// level_db(p) to within 1e-6 dB without a library call (the fits take it ~10^7 times; inline, so the
// gap's inner loop keeps it in registers).
inline double quick_level_db(double p) {
  // p = m 2^e, m in [1, 2), ln m = 2 (s + s^3/3 + ... + s^11/11) with s = (m - 1) / (m + 1) <= 1/3.
  if (!(p > 0.0) || !std::isfinite(p)) return level_db(p);
  std::uint64_t bits;
  std::memcpy(&bits, &p, sizeof bits);
  const int exponent = int((bits >> 52) & 0x7ff) - 1023;
  if (exponent == -1023) return level_db(p);  // subnormal
  bits = (bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
  double m;
  std::memcpy(&m, &bits, sizeof m);
  const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
  const double ln_m = 2.0 * s * (1.0 + s2 * (1.0 / 3 + s2 * (1.0 / 5 + s2 * (1.0 / 7 + s2 * (1.0 / 9 + s2 / 11)))));
  constexpr double kDbPerLn = 4.342944819032518, kDbPerOctave = 3.0102999566398120;
  return kDbPerLn * ln_m + kDbPerOctave * double(exponent);
}

class GapTarget {
 public:
  GapTarget(const AuditData& data, const std::vector<std::size_t>& strikes);
  const std::vector<std::size_t>& strikes() const { return strikes_; }
  // Gap of strikes()[i] against `model` (dB).
  double strike_gap(std::size_t i, const Spectra& model) const;

  // A fit that adds power to a strike's first frames only (a burst) re-reads those alone: the gap's
  // sum and cell count over frames [f, end) of a fixed rendering, for every f and resolution.
  struct FrameTails {
    std::array<std::vector<double>, kResolutions> total;
    std::array<std::vector<std::size_t>, kResolutions> count;
  };
  FrameTails frame_tails(std::size_t i, const Spectra& base) const;
  // Gap of strikes()[i] against `model`, which equals the rendering `tails` was made from beyond its
  // first changed_frames[r] frames.
  double strike_gap(std::size_t i, const Spectra& model, const std::array<std::size_t, kResolutions>& changed_frames,
                    const FrameTails& tails) const;
  // Strike i's clamped measured levels and floor (dB and power) at resolution r.
  const std::vector<double>& measured_db(std::size_t i, std::size_t r) const { return measured_db_[i][r]; }
  double floor_db(std::size_t i, std::size_t r) const { return floor_db_[i][r]; }
  double floor_power(std::size_t i, std::size_t r) const { return floor_power_[i][r]; }

 private:
  // Adds the gap's sum and count over model cells [from, to) at resolution r.
  void accumulate(std::size_t i, std::size_t r, const std::vector<double>& power, std::size_t from, std::size_t to,
                  double& total, std::size_t& count) const;

  std::vector<std::size_t> strikes_;
  std::vector<std::array<std::vector<double>, kResolutions>> measured_db_;
  std::vector<std::array<double, kResolutions>> floor_db_, floor_power_;
};

}  // namespace ms::audit
