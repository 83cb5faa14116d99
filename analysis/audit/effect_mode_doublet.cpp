// mode_doublet: a degenerate mode split by imperfection into two close modes that beat (a periodic
// envelope modulation at the split frequency). Detector: tracks where the extraction resolved two
// modes closer than the merge tolerance in at least half of the strikes. Extension: those modes
// become pairs f -+ split/2 with the measured centre, split and amplitude balance. The centre is the
// members' midpoint, not the track's energy-weighted frequency: an unbalanced pair centred there sits
// off by up to half its split, and its beats with the neighbouring modes drift out of step.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/audit/effect_catalog.hpp"

namespace ms::audit {

namespace {

constexpr double kMinShare = 0.5;  // share of the strikes in which the pair must be resolved

struct Pair {
  double centre_hz, split_hz, balance;
};

// The two strongest members of a track observation as a pair (nothing when fewer than two).
bool pair_of(const TrackObservation& o, Pair& p) {
  if (o.members.size() < 2) return false;
  std::vector<Mode> m = o.members;
  std::sort(m.begin(), m.end(), [](const Mode& a, const Mode& b) { return a.amp > b.amp; });
  const Mode& lo = m[0].freq_hz < m[1].freq_hz ? m[0] : m[1];
  const Mode& hi = m[0].freq_hz < m[1].freq_hz ? m[1] : m[0];
  if (hi.amp < 0.03 * lo.amp || lo.amp < 0.03 * hi.amp) return false;  // a 30 dB partner is a fit artefact
  p.centre_hz = 0.5 * (lo.freq_hz + hi.freq_hz);
  p.split_hz = hi.freq_hz - lo.freq_hz;
  p.balance = hi.amp / (hi.amp + lo.amp);
  return p.split_hz > 0.05;
}

// Tracks split in enough of the given strikes, with their median split and balance.
std::vector<std::pair<std::size_t, Pair>> split_tracks(const AuditData& data, const std::vector<std::size_t>& strikes) {
  std::vector<std::pair<std::size_t, Pair>> out;
  for (std::size_t n = 0; n < data.tracks.size(); ++n) {
    std::vector<double> centre, split, balance;
    std::size_t present = 0;
    for (std::size_t s : strikes) {
      const TrackObservation& o = data.tracks[n].strikes[s];
      if (!o.present) continue;
      ++present;
      Pair p{};
      if (pair_of(o, p)) {
        centre.push_back(p.centre_hz);
        split.push_back(p.split_hz);
        balance.push_back(p.balance);
      }
    }
    if (present > 0 && !split.empty() && double(split.size()) >= kMinShare * double(present))
      out.push_back({n, {median(centre), median(split), median(balance)}});
  }
  return out;
}

Detection detect(const AuditData& data, const AuditModel&) {
  Detection d;
  const auto split = split_tracks(data, all_strikes(data));
  d.statistic = double(split.size());
  d.passes = !split.empty();
  if (split.empty()) {
    d.evidence = "no mode is resolved into a close pair";
    return d;
  }
  const auto& first = split.front();
  char buf[300];
  std::snprintf(buf, sizeof buf, "%zu mode(s) split into close pairs, e.g. %.1f Hz by %.2f Hz, which beats "
                "with a period of %.2f s", split.size(), data.tracks[first.first].freq_hz, first.second.split_hz,
                1.0 / first.second.split_hz);
  d.evidence = buf;
  return d;
}

void extend(const AuditData& data, AuditModel& model, const std::vector<std::size_t>& train) {
  for (const auto& [track, pair] : split_tracks(data, train))
    for (AuditMode& m : model.modes)
      if (m.track == int(track)) {
        m.freq_hz = pair.centre_hz;
        m.doublet.split_hz = pair.split_hz;
        m.doublet.balance = pair.balance;
      }
}

Parameters parameters(const AuditData&, const AuditModel& model) {
  std::vector<double> splits, balances;
  for (const AuditMode& m : model.modes)
    if (m.doublet.split_hz > 0) {
      splits.push_back(m.doublet.split_hz);
      balances.push_back(m.doublet.balance);
    }
  return {{"doublets", double(splits.size())}, {"median_split_hz", median(splits)}, {"median_balance", median(balances)}};
}

}  // namespace

Effect mode_doublet_effect() {
  return {.name = "mode_doublet", .min_strikes = 1, .penalty_db = 0.02,
          .detect = detect, .extend = extend, .parameters = parameters};
}

}  // namespace ms::audit
