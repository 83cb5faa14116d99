// A synthetic room for the independent generator: impulse response = a unit direct impulse, then
// after a pre-delay a diffuse tail of Gaussian noise split into four bands by 4th-order Butterworth
// filters (below 500 Hz, 500-2000, 2000-6000, above 6000 Hz), each band's amplitude falling 60 dB in
// its own RT60, scaled so that direct / reverberant energy is the direct-to-reverberant ratio.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace ms::indep {

constexpr std::array<double, 3> kRoomBandEdgesHz = {500.0, 2000.0, 6000.0};

struct RoomSpec {
  std::array<double, 4> rt60_s{0.5, 0.5, 0.5, 0.5};  // per band, low to high
  double drr_db = 0.0;                              // 10 log10(direct energy / reverberant energy)
  double predelay_s = 0.003;                        // direct sound to the first diffuse energy
};

// The impulse response at sample_rate_hz, 1.5 x the longest RT60 after the pre-delay long.
std::vector<double> room_impulse_response(const RoomSpec& room, double sample_rate_hz, std::uint64_t seed);

// Band b's (0..3) filters applied to x: the split the room's tail is made with.
std::vector<double> room_band(const std::vector<double>& x, std::size_t band, double sample_rate_hz);

}  // namespace ms::indep
