#include "analysis/audit/strikes.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/audit/parallel_indices.hpp"

namespace ms::audit {

MeasuredStrikes prepare_strikes(const std::vector<Recording>& recordings, const StrikeOptions& options) {
  if (recordings.empty()) throw AuditError("no recordings to audit");
  MeasuredStrikes out;
  out.sample_rate_hz = recordings.front().sample_rate_hz;
  for (const Recording& r : recordings)
    if (r.sample_rate_hz != out.sample_rate_hz)
      throw AuditError(r.name + ": sample rate " + std::to_string(std::lround(r.sample_rate_hz)) + " Hz differs from " +
                       recordings.front().name + "'s " + std::to_string(std::lround(out.sample_rate_hz)) +
                       " Hz; resample the recordings to one rate first");
  ExtractOptions extract;
  extract.skip_contact_s = options.skip_contact_s;
  extract.max_attack_skip_s = options.max_attack_skip_s;
  extract.max_dynamic_range_db = options.dynamic_range_db;
  std::size_t common = std::size_t(options.max_duration_s * out.sample_rate_hz);
  for (const Recording& r : recordings)
    if (auto problem = recording_problem(r.samples, r.sample_rate_hz)) throw AuditError(r.name + ": " + *problem);
  // Each strike's extraction stands alone (FFTW's planner is locked in synthesis/fft).
  std::vector<ExtractedFeatures> features(recordings.size());
  parallel_indices(recordings.size(), [&](std::size_t i) {
    features[i] = extract_features(recordings[i].samples, recordings[i].sample_rate_hz, extract);
  });
  for (std::size_t i = 0; i < recordings.size(); ++i) {
    const Recording& r = recordings[i];
    Strike s;
    s.name = r.name;
    s.features = std::move(features[i]);
    if (s.features.modes.empty()) throw AuditError(r.name + ": no modes stand above the noise floor (silence?)");
    s.attack_noise_s = std::max(0.0, s.features.attack_skip_s - options.skip_contact_s);
    const std::size_t onset = std::size_t(std::lround(s.features.onset_s * r.sample_rate_hz));
    s.samples.assign(r.samples.begin() + std::ptrdiff_t(std::min(onset, r.samples.size())), r.samples.end());
    common = std::min(common, s.samples.size());
    out.strikes.push_back(std::move(s));
  }
  if (double(common) < options.min_duration_s * out.sample_rate_hz)
    throw AuditError("recordings last less than " + std::to_string(options.min_duration_s) +
                     " s after the strike; an audit needs the decay");
  out.grids = make_grids(out.sample_rate_hz, common);
  for (Strike& s : out.strikes) {
    s.samples.resize(common);
    s.spectra = bark_spectra(s.samples, out.grids);
  }
  return out;
}

}  // namespace ms::audit
