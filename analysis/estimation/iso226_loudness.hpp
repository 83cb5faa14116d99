// Loudness of pure tones: ISO 226:2003 normal equal-loudness-level contours (SPL <-> phon) and the
// phon -> sone map. Used by the perceptual image metric (loudness_image.hpp).
//
// ISO 226:2003, clause 4, Table 1 gives alpha_f (exponent for loudness perception), L_U (magnitude of
// the linear transfer function normalised at 1 kHz, dB) and T_f (threshold of hearing, dB) at 29
// frequencies, 20 Hz .. 12.5 kHz, and
//   Eq. (1)  L_p = (10/alpha_f) lg A_f - L_U + 94                                    [dB SPL]
//            A_f = 4.47e-3 (10^(0.025 L_N) - 1.15) + (0.4 10^((T_f + L_U)/10 - 9))^alpha_f
//   Eq. (2)  L_N = 40 lg B_f + 94                                                    [phon]
//            B_f = (0.4 10^((L_p + L_U)/10 - 9))^alpha_f - (0.4 10^((T_f + L_U)/10 - 9))^alpha_f + 0.005135
// (the 2003 constants; ISO 226:2023 changed 1.15 -> 1.14 and 0.005135 -> 0.005076). The standard
// states the contours for 20-90 phon up to 4 kHz and 20-80 phon from 5 to 12.5 kHz; the functions
// here evaluate the formulas outside that range too, as the metric needs them at every level.
#pragma once
#include <array>

namespace ms {

struct Iso226Row {
  double freq_hz = 0.0;
  double alpha_f = 0.0;  // exponent for loudness perception
  double lu_db = 0.0;    // L_U: linear transfer function normalised at 1 kHz
  double tf_db = 0.0;    // T_f: threshold of hearing [dB SPL]
};

// ISO 226:2003 Table 1, the 29 preferred frequencies in ascending order.
const std::array<Iso226Row, 29>& iso226_table();

// The contour parameters at any frequency: linear in log frequency between neighbouring rows (a row's
// own frequency returns that row exactly), the end rows outside 20 Hz .. 12.5 kHz (the standard has
// nothing there; the images' bands below 20 Hz hold no modal energy, and above 12.5 kHz the 12.5 kHz
// threshold is the nearest stated one).
Iso226Row iso226_parameters(double freq_hz);

// Eq. (1): SPL [dB] of a pure tone at `row`'s frequency with loudness level loudness_phon.
double iso226_spl_db(const Iso226Row& row, double loudness_phon);

// Eq. (2): loudness level [phon] of a pure tone of spl_db at `row`'s frequency. Far below the
// threshold it goes negative (0 sone); -infinity would mean B_f <= 0, which no row of Table 1 reaches
// (their T_f terms all stay under 0.005135). Eq. (2) inverts Eq. (1) to 0.06 phon (the standard
// rounds their constants separately).
double iso226_loudness_phon(const Iso226Row& row, double spl_db);

// Loudness [sone] of a loudness level [phon]: 2^((L_N - 40)/10) from 40 phon up (1 sone at 40 phon,
// doubling every 10 phon); below 40 phon the power law (L_N/40)^2.642, which meets it at 40 phon and
// is 0 at 0 phon (loudness near threshold falls faster than the 10-phon doubling says); 0 at or below
// 0 phon.
double sone_from_phon(double loudness_phon);

// The chain mean square -> dB SPL -> phon -> sone at one frequency, with the constants of Eq. (2)
// folded so that one call costs two pow and one log10: the image metric converts every pixel with it.
// db_spl_at_unit_power: SPL of a mean-square value of 1 (digital units squared), the calibration.
class ToneLoudness {
 public:
  ToneLoudness(const Iso226Row& row, double db_spl_at_unit_power);
  double sone(double mean_square) const;
  double phon(double mean_square) const;

 private:
  double alpha_f_ = 0.0;
  double gain_ = 0.0;    // (0.4 10^((offset + L_U)/10 - 9))^alpha_f
  double offset_ = 0.0;  // - (0.4 10^((T_f + L_U)/10 - 9))^alpha_f + 0.005135
};

}  // namespace ms
