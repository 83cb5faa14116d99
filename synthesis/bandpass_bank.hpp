// BandpassBank: filter-based modal synthesis as Skandalou & Ireland (2017, section 4.3.1.2) built it in
// Pure Data: a unit impulse (Eq 4.1), scaled by the strike's gain (the patch's impact magnitude), through
// one [bp~] band-pass filter per mode centred on the mode's frequency, each output times the mode's
// amplitude, summed and sent through a clipper ([clip~ -1 1], the patch's last step before the DAC).
// The mode's decay_per_s and phase are not used: in this method Q alone sets how long a mode rings.
//
// [bp~] as Pure Data computes it (src/d_filter.c, sigbp_docoef and sigbp_perform, github.com/pure-data/
// pure-data), in single precision like Pd's default build, for centre f (Hz), Q and sample rate fs:
//   f < 0.001 is taken as 10 Hz; Q < 0 as 0
//   omega = f (2 * 3.14159) / fs                      (Pd's own value of pi)
//   1 - r = omega / Q, at most 1 (and 1 for Q < 0.001)
//   coef1 = 2 qcos(omega) r,   qcos(w) = 1 - w^2/2 + w^4/24 - w^6/720 for |w| <= pi/2, else 0
//   coef2 = -r^2,              gain = 2 (1 - r) ((1 - r) + r omega)
//   w[n] = x[n] + coef1 w[n-1] + coef2 w[n-2],   y[n] = gain w[n]
// with the state flushed to 0 at the end of each 64-sample DSP block when it is denormal, infinite or
// NaN (PD_BIGORSMALL). So a mode decays at about -fs ln r = 2 pi f / Q per second, its impulse response
// starts at about 2 omega / Q times its amplitude (higher modes louder: the method's spectral tilt), and
// above fs/4 the truncated cosine is 0, so such a filter rings at fs/4 whatever its centre.
//
// The materials' Q: the thesis gives two ranges that disagree. Table 4.1 (the tool's defaults, chosen
// by trial and error) has plastic 1000, wood 1500, ceramic 3000, glass 3500, metal 4000; the text of
// section 4.3.1.2 says Q "range[s] from about 20 for plastic to 5000 for metal", naming no value in
// between (here: log-spaced between the two ends, as a stand-in). Table 4.1 is the default: it is what
// the experiments used (experiment 3 swept Q from 1000 in steps of 200 to 4600 to validate exactly those
// values, and its listeners' change points fall on them, section 5.4.3).
#pragma once
#include <cstddef>
#include <vector>

#include "synthesis/modal_model.hpp"
#include "synthesis/name_table.hpp"

namespace ms {

enum class BandpassMaterial { plastic, wood, ceramic, glass, metal };
inline constexpr NameTable<BandpassMaterial, 5> kBandpassMaterialNames{{{BandpassMaterial::plastic, "plastic"},
                                                                         {BandpassMaterial::wood, "wood"},
                                                                         {BandpassMaterial::ceramic, "ceramic"},
                                                                         {BandpassMaterial::glass, "glass"},
                                                                         {BandpassMaterial::metal, "metal"}}};

// Which of the thesis's two Q ranges a material's Q comes from.
enum class QTable { table_4_1, section_4_3_1_2 };
inline constexpr NameTable<QTable, 2> kQTableNames{
    {{QTable::table_4_1, "table_4_1"}, {QTable::section_4_3_1_2, "section_4_3_1_2"}}};

// Table 4.1: 1000, 1500, 3000, 3500, 4000. Section 4.3.1.2: 20 (plastic) to 5000 (metal), the three
// between log-spaced (79.5, 316, 1257).
double material_q(BandpassMaterial material, QTable table = QTable::table_4_1);

// One [bp~] filter's coefficients, computed as sigbp_docoef does.
struct PdBandpassCoefficients {
  float coef1 = 0.0f, coef2 = 0.0f, gain = 0.0f;
};
PdBandpassCoefficients pd_bandpass_coefficients(double centre_hz, double q, double sample_rate_hz);

class BandpassBank {
 public:
  static constexpr std::size_t kPdBlockFrames = 64;  // Pd's DSP block: where the state is flushed

  // q: one per mode of `model`, or a single value for all. Modes at or above Nyquist (or at or below
  // 0 Hz) do not sound. impulse: the impulse's height (the strike's gain); clip: the clipper's level
  // (|y| <= clip), 0 for none. Throws std::invalid_argument when q has another length.
  BandpassBank(const ModalModel& model, const std::vector<double>& q, double impulse, double clip,
               double sample_rate_hz);

  // Writes the next `frames` samples (overwrites out). Allocation-free.
  void render(float* out, std::size_t frames);

  std::size_t filter_count() const { return coef1_.size(); }

 private:
  std::vector<float> coef1_, coef2_, gain_, amp_;  // per filter
  std::vector<float> last_, prev_;                 // per filter: w[n-1], w[n-2]
  float impulse_ = 1.0f;
  float clip_ = 1.0f;
  std::size_t position_ = 0;  // samples emitted so far
};

// Convenience: the whole signal (allocates the output).
std::vector<float> render_bandpass(const ModalModel& model, const std::vector<double>& q, double impulse,
                                   double clip, double sample_rate_hz, std::size_t frames);

}  // namespace ms
