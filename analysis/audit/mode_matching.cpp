#include "analysis/audit/mode_matching.hpp"

#include <algorithm>
#include <cmath>

namespace ms::audit {

std::size_t ModeTrack::presence() const {
  return std::size_t(std::count_if(strikes.begin(), strikes.end(), [](const auto& o) { return o.present; }));
}

std::vector<ModeTrack> match_modes(const std::vector<std::vector<Mode>>& per_strike, const MatchOptions& options) {
  struct Item {
    double freq_hz;
    std::size_t strike;
    Mode mode;
  };
  std::vector<Item> all;
  for (std::size_t s = 0; s < per_strike.size(); ++s)
    for (const Mode& m : per_strike[s]) all.push_back({m.freq_hz, s, m});
  // Clusters grow around anchors, the most energetic components first (energy amp^2 / decay): each
  // component joins the nearest anchor within the tolerance or anchors a cluster of its own. Chaining
  // each component to its neighbour instead would let a run of weak components (a room's answer
  // around its modes) join two modes tens of Hz apart into one track.
  const auto energy = [](const Mode& m) { return m.amp * m.amp / std::max(m.decay_per_s, 1e-9); };
  std::vector<std::size_t> by_energy(all.size());
  for (std::size_t k = 0; k < all.size(); ++k) by_energy[k] = k;
  std::stable_sort(by_energy.begin(), by_energy.end(),
                   [&](std::size_t a, std::size_t b) { return energy(all[a].mode) > energy(all[b].mode); });
  std::vector<double> anchor_hz;
  std::vector<std::vector<std::size_t>> clusters;
  for (std::size_t k : by_energy) {
    const double f = all[k].freq_hz;
    std::size_t nearest = clusters.size();
    for (std::size_t c = 0; c < clusters.size(); ++c) {
      const double distance = std::abs(f - anchor_hz[c]);
      if (distance <= std::max(options.merge_rel * anchor_hz[c], options.merge_hz) &&
          (nearest == clusters.size() || distance < std::abs(f - anchor_hz[nearest])))
        nearest = c;
    }
    if (nearest == clusters.size()) {
      anchor_hz.push_back(f);
      clusters.emplace_back();
    }
    clusters[nearest].push_back(k);
  }
  std::vector<ModeTrack> tracks;
  const std::size_t strikes = per_strike.size();
  const std::size_t need = std::max<std::size_t>(1, std::size_t(std::ceil(options.min_presence * double(strikes) - 1e-9)));
  for (const std::vector<std::size_t>& cluster : clusters) {
    ModeTrack t;
    t.strikes.assign(strikes, {});
    for (std::size_t k : cluster) t.strikes[all[k].strike].members.push_back(all[k].mode);
    std::vector<double> freqs;
    for (TrackObservation& o : t.strikes) {
      if (o.members.empty()) continue;
      // One physical mode: a member decaying many times faster or slower than the strike's most
      // energetic member (power amp^2 / decay) is something else at that frequency, e.g. a burst
      // of attack noise the fit took for a fast mode, and would swamp the mode's amplitude.
      const auto power = [](const Mode& m) { return m.amp * m.amp / std::max(m.decay_per_s, 1e-9); };
      const Mode main = *std::max_element(o.members.begin(), o.members.end(),
                                          [&](const Mode& a, const Mode& b) { return power(a) < power(b); });
      std::erase_if(o.members, [&](const Mode& m) {
        const double ratio = m.decay_per_s / main.decay_per_s;
        return ratio > options.max_decay_ratio || ratio < 1.0 / options.max_decay_ratio;
      });
      double e = 0.0, fe = 0.0, de = 0.0;
      for (const Mode& m : o.members) {
        const double w = m.amp * m.amp;
        e += w;
        fe += w * m.freq_hz;
        de += w * m.decay_per_s;
      }
      o.present = e > 0.0;
      if (!o.present) continue;
      o.freq_hz = fe / e;
      o.decay_per_s = de / e;
      o.amp = std::sqrt(e);
      freqs.push_back(o.freq_hz);
    }
    if (freqs.size() >= need) {
      std::sort(freqs.begin(), freqs.end());
      t.freq_hz = freqs[freqs.size() / 2];
      tracks.push_back(std::move(t));
    }
  }
  std::sort(tracks.begin(), tracks.end(), [](const ModeTrack& a, const ModeTrack& b) { return a.freq_hz < b.freq_hz; });
  return tracks;
}

}  // namespace ms::audit
