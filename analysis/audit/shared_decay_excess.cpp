#include "analysis/audit/shared_decay_excess.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/distributions/fisher_f.hpp>

namespace ms::audit {

SharedDecayExcess shared_decay_excess(const AuditData& data) {
  double strongest = 0.0;
  for (const ModeTrack& t : data.tracks)
    for (const TrackObservation& o : t.strikes) strongest = std::max(strongest, o.amp);
  const std::size_t strikes = data.strike_count();
  std::vector<std::vector<double>> log_decay;  // [mode][strike]
  for (const ModeTrack& t : data.tracks) {
    double loudest = 0.0;
    bool everywhere = t.strikes.size() == strikes;
    for (const TrackObservation& o : t.strikes) {
      loudest = std::max(loudest, o.amp);
      // A resolved doublet's merged decay is less reliable.
      everywhere = everywhere && o.present && o.members.size() == 1 && o.decay_per_s > 0.0;
    }
    if (!everywhere || loudest < kStrongTrackWithin * strongest) continue;
    std::vector<double> row;
    for (const TrackObservation& o : t.strikes) row.push_back(std::log(o.decay_per_s));
    log_decay.push_back(std::move(row));
  }
  const std::size_t modes = log_decay.size();
  if (modes < kMinSharedModes || strikes < 2) return {0.0, 1.0, modes};
  std::vector<double> mode_mean(modes, 0.0), strike_mean(strikes, 0.0);
  double grand = 0.0;
  for (std::size_t n = 0; n < modes; ++n)
    for (std::size_t s = 0; s < strikes; ++s) {
      mode_mean[n] += log_decay[n][s] / double(strikes);
      strike_mean[s] += log_decay[n][s] / double(modes);
      grand += log_decay[n][s] / double(modes * strikes);
    }
  double ss_strike = 0.0, ss_residual = 0.0;
  for (std::size_t s = 0; s < strikes; ++s) ss_strike += double(modes) * (strike_mean[s] - grand) * (strike_mean[s] - grand);
  for (std::size_t n = 0; n < modes; ++n)
    for (std::size_t s = 0; s < strikes; ++s) {
      const double r = log_decay[n][s] - mode_mean[n] - strike_mean[s] + grand;
      ss_residual += r * r;
    }
  const double df_strike = double(strikes - 1), df_residual = double((strikes - 1) * (modes - 1));
  if (!(ss_residual > 0.0)) return {0.0, ss_strike > 0.0 ? 0.0 : 1.0, modes};
  const double f = (ss_strike / df_strike) / (ss_residual / df_residual);
  return {f, boost::math::cdf(boost::math::complement(boost::math::fisher_f(df_strike, df_residual), f)), modes};
}

}  // namespace ms::audit
