// Mode matching across strikes: the modes extracted from each strike are grouped into tracks, one
// per physical mode of the object. Tracks grow around anchors, the most energetic components first:
// a component within the doublet tolerance of an anchor joins the nearest one (the plain model has
// one mode there; a split pair is the mode_doublet effect's business), any other anchors its own.
#pragma once
#include <cstddef>
#include <vector>

#include "synthesis/modal_model.hpp"

namespace ms::audit {

struct TrackObservation {
  bool present = false;
  double freq_hz = 0.0;      // energy-weighted over the members
  double decay_per_s = 0.0;  // energy-weighted over the members
  double amp = 0.0;          // sqrt(sum amp^2) of the members
  std::vector<Mode> members; // the extracted modes merged here (2 for a resolved doublet)
};

struct ModeTrack {
  double freq_hz = 0.0;                  // median over the strikes where present
  std::vector<TrackObservation> strikes; // one per strike
  std::size_t presence() const;
};

struct MatchOptions {
  double merge_rel = 0.004;     // modes within 0.4 % ...
  double merge_hz = 8.0;        // ... or 8 Hz of each other are one track (doublets beat slower than 8 Hz)
  double min_presence = 0.5;    // a track must appear in at least this share of the strikes
  double max_decay_ratio = 4.0; // members of one strike's track decay within this factor of its main one
};

// per_strike[s] = extracted modes of strike s. Tracks ascending in frequency.
std::vector<ModeTrack> match_modes(const std::vector<std::vector<Mode>>& per_strike, const MatchOptions& options = {});

}  // namespace ms::audit
