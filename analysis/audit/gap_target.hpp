// The gap of many candidate predictions against the same measured strikes (a fit evaluates hundreds):
// the measured levels are clamped to their floors once; the arithmetic is gap_map's, with the model's
// levels taken to within 1e-6 dB by a polynomial.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "analysis/audit/audit_model.hpp"

namespace ms::audit {

// level_db(p) to within 1e-6 dB without a library call (the fits take it ~10^7 times).
double quick_level_db(double power);

class GapTarget {
 public:
  GapTarget(const AuditData& data, const std::vector<std::size_t>& strikes);
  const std::vector<std::size_t>& strikes() const { return strikes_; }
  // Gap of strikes()[i] against `model` (dB).
  double strike_gap(std::size_t i, const Spectra& model) const;
  // Strike i's clamped measured levels and floor at resolution r.
  const std::vector<double>& measured_db(std::size_t i, std::size_t r) const { return measured_db_[i][r]; }
  double floor_db(std::size_t i, std::size_t r) const { return floor_db_[i][r]; }

 private:
  std::vector<std::size_t> strikes_;
  std::vector<std::array<std::vector<double>, kResolutions>> measured_db_;
  std::vector<std::array<double, kResolutions>> floor_db_, floor_power_;
};

}  // namespace ms::audit
