// A room: the direct sound convolved with the room's impulse response, so every mode gets a tail
// coloured by its own spectrum (a tail added from the onset, effects.hpp's Reverb, is white instead).
// The response is a unit direct impulse followed by seeded Gaussian noise that decays 60 dB in RT60
// in each octave band, scaled so that the direct energy over the reverberant energy is drr_db.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ms {

// Octave bands of a room's RT60s; band edges at the geometric means of neighbouring centres, the
// lowest band reaching down to 0 Hz and the highest up to Nyquist.
inline constexpr std::array<double, 7> kRoomOctaveCentresHz{125, 250, 500, 1000, 2000, 4000, 8000};
std::size_t room_octave_band(double freq_hz);
double room_octave_lower_edge_hz(std::size_t band);  // 0 for the lowest band
double room_octave_upper_edge_hz(std::size_t band);  // infinity for the highest band

struct Room {
  std::vector<double> rt60_s;  // one value for every band, or one per octave band
  double drr_db = 0.0;         // direct energy / reverberant energy (dB)
  std::uint64_t seed = 0;
  bool enabled = false;

  double band_rt60_s(std::size_t band) const { return rt60_s.size() == 1 ? rt60_s[0] : rt60_s[band]; }
};

// The room's impulse response at sample_rate_hz: h[0] = 1, then the reverberant noise until the
// slowest band has decayed 60 dB.
std::vector<float> room_impulse_response(const Room& room, double sample_rate_hz);

// samples <- samples * impulse_response (FFT overlap-add), cut to samples' length (a strike keeps its
// duration).
void convolve_overlap_add(std::vector<float>& samples, const std::vector<float>& impulse_response);

// The room applied to a direct sound (nothing when the room is not enabled).
void apply_room(std::vector<float>& samples, double sample_rate_hz, const Room& room);

}  // namespace ms
