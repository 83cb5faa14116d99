// ISO 226:2003 equal-loudness contours and phon -> sone; see iso226_loudness.hpp.
#include "analysis/estimation/iso226_loudness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ms {

const std::array<Iso226Row, 29>& iso226_table() {
  // ISO 226:2003 "Acoustics - Normal equal-loudness-level contours", Table 1 (f, alpha_f, L_U, T_f).
  static const std::array<Iso226Row, 29> table{{
      {20.0, 0.532, -31.6, 78.5},   {25.0, 0.506, -27.2, 68.7},   {31.5, 0.480, -23.0, 59.5},
      {40.0, 0.455, -19.1, 51.1},   {50.0, 0.432, -15.9, 44.0},   {63.0, 0.409, -13.0, 37.5},
      {80.0, 0.387, -10.3, 31.5},   {100.0, 0.367, -8.1, 26.5},   {125.0, 0.349, -6.2, 22.1},
      {160.0, 0.330, -4.5, 17.9},   {200.0, 0.315, -3.1, 14.4},   {250.0, 0.301, -2.0, 11.4},
      {315.0, 0.288, -1.1, 8.6},    {400.0, 0.276, -0.4, 6.2},    {500.0, 0.267, 0.0, 4.4},
      {630.0, 0.259, 0.3, 3.0},     {800.0, 0.253, 0.5, 2.2},     {1000.0, 0.250, 0.0, 2.4},
      {1250.0, 0.246, -2.7, 3.5},   {1600.0, 0.244, -4.1, 1.7},   {2000.0, 0.243, -1.0, -1.3},
      {2500.0, 0.243, 1.7, -4.2},   {3150.0, 0.243, 2.5, -6.0},   {4000.0, 0.242, 1.2, -5.4},
      {5000.0, 0.242, -2.1, -1.5},  {6300.0, 0.245, -7.1, 6.0},   {8000.0, 0.254, -11.2, 12.6},
      {10000.0, 0.271, -10.7, 13.9}, {12500.0, 0.301, -3.1, 12.3},
  }};
  return table;
}

Iso226Row iso226_parameters(double freq_hz) {
  const auto& t = iso226_table();
  if (!(freq_hz > t.front().freq_hz)) return t.front();
  if (freq_hz >= t.back().freq_hz) return t.back();
  const auto hi = std::upper_bound(t.begin(), t.end(), freq_hz,
                                   [](double f, const Iso226Row& r) { return f < r.freq_hz; });
  const auto lo = hi - 1;
  if (lo->freq_hz == freq_hz) return *lo;
  const double u = std::log(freq_hz / lo->freq_hz) / std::log(hi->freq_hz / lo->freq_hz);
  auto mix = [u](double a, double b) { return a + u * (b - a); };
  return {freq_hz, mix(lo->alpha_f, hi->alpha_f), mix(lo->lu_db, hi->lu_db), mix(lo->tf_db, hi->tf_db)};
}

namespace {
// (0.4 10^((L + L_U)/10 - 9))^alpha_f, the term both equations share.
double transfer_term(const Iso226Row& r, double level_db) {
  return std::pow(0.4 * std::pow(10.0, (level_db + r.lu_db) / 10.0 - 9.0), r.alpha_f);
}
}  // namespace

double iso226_spl_db(const Iso226Row& r, double loudness_phon) {
  const double af = 4.47e-3 * (std::pow(10.0, 0.025 * loudness_phon) - 1.15) + transfer_term(r, r.tf_db);
  return 10.0 / r.alpha_f * std::log10(af) - r.lu_db + 94.0;
}

double iso226_loudness_phon(const Iso226Row& r, double spl_db) {
  const double bf = transfer_term(r, spl_db) - transfer_term(r, r.tf_db) + 0.005135;
  return bf > 0.0 ? 40.0 * std::log10(bf) + 94.0 : -std::numeric_limits<double>::infinity();
}

double sone_from_phon(double phon) {
  if (!(phon > 0.0)) return 0.0;
  if (phon >= 40.0) return std::exp2((phon - 40.0) / 10.0);
  return std::pow(phon / 40.0, 2.642);
}

ToneLoudness::ToneLoudness(const Iso226Row& r, double db_spl_at_unit_power)
    : alpha_f_(r.alpha_f), gain_(transfer_term(r, db_spl_at_unit_power)),
      offset_(0.005135 - transfer_term(r, r.tf_db)) {}

// (0.4 10^((L_p + L_U)/10 - 9))^a with L_p = offset + 10 lg P is gain * P^a.
double ToneLoudness::phon(double mean_square) const {
  const double bf = gain_ * std::pow(mean_square, alpha_f_) + offset_;
  return bf > 0.0 ? 40.0 * std::log10(bf) + 94.0 : -std::numeric_limits<double>::infinity();
}

double ToneLoudness::sone(double mean_square) const {
  if (!(mean_square > 0.0)) return 0.0;
  return sone_from_phon(phon(mean_square));
}

}  // namespace ms
