// Fit of a room (synthesis/room_response's effects.room) to the recordings: the RT60 of each octave
// band and the direct-to-reverberant ratio that minimise the mean gap over the given strikes, a room
// answering every strike alike. The model's modes are rendered once; the room's expected power is
// added in closed form (room_power.hpp) for each candidate.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "analysis/audit/audit_model.hpp"
#include "synthesis/room_response.hpp"

namespace ms::audit {

constexpr double kMinRoomRt60S = 0.1, kMaxRoomRt60S = 3.0;
constexpr double kMinRoomDrrDb = -15.0, kMaxRoomDrrDb = 30.0;
// A room strong enough to scatter the extracted decays: tuning rooms support_damping outscored were
// fitted at DRR 3.0-12.8 dB; the real Paiste and low agogo bells, whose long faint tails fit as rooms
// of DRR 25 and 21 dB, are better explained by support damping first. In such a room hand damping's
// per-strike decays also change each mode's reverberant answer (its amplitudes are read again).
constexpr double kScatteringRoomDrrDb = 15.0;

struct RoomFit {
  Room room;                           // rt60_s per octave band, drr_db (enabled)
  std::vector<bool> band_measured;     // false: no mode in the band (its RT60 is the curve's)
  double gap_db = 0.0;                 // mean gap over the strikes with the room
  double grid_cv_gap_db = 0.0;         // leave-one-strike-out gap of the coarse grid or of a small grid
                                       // around the fitted room, the lower (grid_cross_validation.hpp)
};

// `without` must not contain a room. Coarse: one RT60 for every band and the DRR on a grid; then log
// RT60 as a quadratic over the octave bands and the reverberant level by Nelder-Mead (rooms' RT60s
// vary smoothly with frequency, and a band whose modes all outlast the room barely moves the gap).
// coarse_only: the grid's room (one RT60 for every band), for quick comparisons. start: a room the
// amplitudes were read in, also a candidate (its RT60s taken to the nearest such curve); the search
// starts from it where it beats the grid's best (from the grid alone a room read in a strong guess can
// fall back to a weak one).
RoomFit fit_room(const AuditData& data, const AuditModel& without, const std::vector<std::size_t>& strikes,
                 bool coarse_only = false, const Room* start = nullptr);

// Per mode of a model: the factor on its dry amplitude (0: the mode is left out) and the room's answer
// to it (AuditMode::room_answer), read from the spectrograms.
struct ModeReading {
  std::vector<double> factor, answer;
  // room_gain times the factor, room_answer set.
  void apply(AuditModel& model) const;
};

// With `room` in the model, each mode's amplitude read again from the strikes' spectrograms, one mode
// after another (in a room the extraction's amplitude of a mode also holds parts of its reverberation
// and its neighbours', and some tracks are the room's answer to a stronger mode): the factor on the
// mode's dry amplitude in [0.1, 3] that lowers the mean gap most, or 0 where leaving it out does better
// and may_drop[n] allows it. The room's answers stay as they are (a room being fitted is a guess).
ModeReading read_mode_amplitudes(const AuditData& data, const AuditModel& without, const Room& room,
                                 const std::vector<std::size_t>& strikes, const std::vector<bool>& may_drop);

// The model's own room kept, every mode's room_gain read again (none dropped) with the room's answer to
// it, in up to two passes while the gap over `strikes` falls: the amplitudes were read in a guessed room,
// and reading scores each mode on a prediction linearised around the renderings, so a second rendering
// reads them closer. A room's response at a mode's frequency is one draw of its noise, the same on
// every strike: a slow mode settles above or below its direct sound by that draw, within what the
// room's level allows (room_power.hpp: mode_answer_range). Returns the mean gap over `strikes` of the
// model read; nothing happens without a room (nullopt).
std::optional<double> read_amplitudes_in_room(const AuditData& data, AuditModel& model,
                                              const std::vector<std::size_t>& strikes);

}  // namespace ms::audit
