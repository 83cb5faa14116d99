// What a room (synthesis/room_response: a unit direct impulse, then Gaussian noise split into octave
// bands that each decay 60 dB in their RT60, scaled to a direct-to-reverberant ratio) adds to a modal
// rendering, in expectation over the room's noise, on the audit's Bark spectrogram grids.
//
// For a mode x(t) = a e^{-d t} sin(w t) and a reverberant part r of white-equivalent variance sigma^2
// e^{-2 k t} around w (k = ln 1000 / RT60 of the mode's octave band), E[(x * r)^2](t) =
// sigma^2 (a^2 / 2) (e^{-2 k t} - e^{-2 d t}) / (2 (d - k)) (t e^{-2 d t} when d = k): a slow mode
// (d < k) grows towards (1 + sigma^2 / (2 (k - d))) times its own power, a fast one leaves a tail at
// the room's rate. That narrowband part reaches neighbouring Bark bands through the analysis window
// as the mode itself does. Away from the modes, the rendering's spectrum (all modes' onsets, summed
// coherently: they start together) is a transient the room turns into a tail at that band's rate.
// Both are closed forms per frame.
//
// The audit's mode amplitudes are measured ones: in a room, each slow mode's amplitude is multiplied
// by the room's response at its pole, the same on every strike, so the extraction already carries it:
// the dry amplitude is the measured one over the square root of that gain's expected power. The
// room's actual answer at a mode's frequency is one draw of its noise: a mode's reverberant part may be
// scaled by an `answer` read from the recordings (room_fit.hpp).
#pragma once
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "analysis/audit/gap_metric.hpp"
#include "synthesis/modal_model.hpp"
#include "synthesis/room_response.hpp"

namespace ms::audit {

constexpr std::size_t kRoomBands = kRoomOctaveCentresHz.size();

// A room's decay per octave band and its reverberant noise level, per sample.
struct RoomRates {
  std::array<double, kRoomBands> k_per_sample{};  // amplitude decay rate of each octave band
  double sigma2 = 0.0;                             // white-equivalent variance of h[1]
};

// Rates from RT60s, and the level from the DRR: the expected reverberant energy of the impulse
// response, sigma^2 sum_b share_b sum_{i >= 1} e^{-2 k_b i} (share_b: the band's part of the spectrum),
// is 10^(-drr / 10).
RoomRates room_rates(const Room& room, double sample_rate_hz);
// ... and back: the DRR of a room with these rates and level.
double room_drr_db(const RoomRates& rates, double sample_rate_hz);
// sigma^2 for a DRR given the rates.
double room_sigma2(const std::array<double, kRoomBands>& k_per_sample, double drr_db, double sample_rate_hz);

// The reverberant-to-direct energy q of octave band b (what a narrowband sound there gains).
double band_reverb_ratio(const RoomRates& rates, std::size_t band);

// Per-grid constants: the Bark bands' edges and octave bands.
struct RoomGrid {
  std::vector<double> band_lo_hz, band_hi_hz;  // Bark band edges on the grid's bins
  std::vector<std::size_t> band_octave;        // octave band of each Bark band's centre
};
RoomGrid room_grid(const SpectrogramGrid& grid);

// Where a steady tone at freq_hz lands on the grid's Bark bands through the Hann window: (band, share
// of its power), shares below 1e-6 left out.
std::vector<std::pair<std::size_t, double>> window_leakage(const SpectrogramGrid& grid, double freq_hz);

// sum_{j < n} w_j^2 e^{-2 r j} for the Hann window of n samples (closed form).
double hann2_decay_sum(double r_per_sample, std::size_t n);

// What a room needs to know of one strike's rendered modes on one grid (independent of the room):
// each mode's narrowband share, window leakage and decay, and per Bark band the energy of the
// onset's spectrum from the modes outside that band, split by the octave band of the modes (a 7 x 7
// Gram matrix, so that scaling each octave's amplitudes scales it exactly).
struct RoomFootprint {
  struct ModeTerms {
    std::size_t octave = 0;
    double delta = 0.0;         // decay per sample
    double a2 = 0.0;            // amplitude^2 as rendered
    double own_share = 1.0;     // part of its spectrum in its own Bark band
    double window_sum = 0.0;    // sum_j w_j^2 e^{-2 delta j}
    double per_hop = 0.0;       // e^{-2 delta hop}
    double ramp_sum = 0.0;      // sum_j w_j^2 j e^{-2 delta j} (for d = k)
    double rendered_scale = 1.0;  // dry_power_scale the rendering applied (1: measured amplitudes)
    double extra_power = 1.0;     // the mode's power relative to its rendering beyond the dry scaling
    double answer = 1.0;          // its reverberant part over the room's expected one (AuditMode::room_answer)
    std::size_t owner = 0;        // index of the rendered mode it came from
    std::vector<std::pair<std::size_t, double>> leakage;
  };
  std::vector<ModeTerms> modes;
  std::vector<std::array<double, kRoomBands * kRoomBands>> onset_gram;  // [band][octave x octave]
  std::array<double, kRoomBands> onset_scale{};  // the rendering's dry_power_scale of each octave's onsets
};
// `rendered`: the modes as rendered; `as_rendered`: the room whose dry amplitudes they are (none:
// measured amplitudes).
RoomFootprint room_footprint(const SpectrogramGrid& grid, const RoomGrid& room_grid, const ModalModel& rendered,
                             const RoomRates* as_rendered = nullptr);

// Measured amplitude^2 to dry for a mode of decay delta (per sample) in octave band `band`.
double dry_power_scale(const RoomRates& rates, std::size_t band, double delta_per_sample);

// The window sums of a room's octave rates on a grid.
struct RoomFrameSums {
  std::array<double, kRoomBands> frame_sum{};  // sum_j w_j^2 e^{-2 k_b j}
  std::array<double, kRoomBands> per_hop{};    // e^{-2 k_b hop}
};
RoomFrameSums room_frame_sums(const SpectrogramGrid& grid, const RoomRates& rates);

// An answer below expectation cancels part of a mode's direct sound, never all of it: at least this
// share of the direct power stays.
constexpr double kMinAnsweredShare = 0.01;

// Mode m per frame (before the window's leakage over bands): its rendered power (closed form) and
// what the room adds to it (the dry scaling and the reverberant part times m.answer); `frames` values
// each. reverberant (optional): the reverberant part alone at answer 1.
void mode_frame_powers(const RoomFootprint::ModeTerms& m, const SpectrogramGrid& grid, const RoomRates& rates,
                       const RoomFrameSums& sums, std::size_t frames, double* rendered, double* added,
                       double* reverberant = nullptr);

// The factor on a mode's rendered power that gives its direct part in the room.
double mode_dry_factor(const RoomFootprint::ModeTerms& m, const RoomRates& rates);

// The power a slow mode settles at in the room over its direct power, in expectation (1 + q); 0 for a
// mode that decays as fast as the room or faster (its reverberant part is a tail, not a gain).
double mode_reverb_ratio(const RoomFootprint::ModeTerms& m, const RoomRates& rates);

// The range of m.answer a room of noise allows a slow mode: its response there is 1 + h with h complex
// Gaussian of power q, so the settled power |1 + h|^2 stays within (1 -+ 2 sqrt q)^2 but rarely.
// Faster modes: a tail of the room's noise, between a quarter and three times its expected power.
std::pair<double, double> mode_answer_range(const RoomFootprint::ModeTerms& m, const RoomRates& rates);

// Measured amplitudes to dry ones (in place).
void make_dry(ModalModel& modes, const RoomRates& rates, double sample_rate_hz);

// The room's expected power added to spec, which holds the footprint's modes as rendered: each mode's
// own power times (its dry_power_scale under `rates` over the one it was rendered with, minus 1) in
// closed form (0 when the rendering has this room's dry amplitudes), and the dry modes' reverberant
// part.
void add_room_power(BarkSpectrogram& spec, const SpectrogramGrid& grid, const RoomGrid& room_grid,
                    const RoomFootprint& footprint, const RoomRates& rates);

}  // namespace ms::audit
